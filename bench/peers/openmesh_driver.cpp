// SPDX-License-Identifier: MIT
// OpenMesh (9.0) Loop driver: DRIVER loop MESH.obj LEVELS
// TriMesh_ArrayKernelT<> (float Vec3f points) built from the OBJ (untimed); timed:
// Subdivider::Uniform::LoopT attach + operator()(mesh, LEVELS) + detach.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include "peer_common.hpp"

typedef OpenMesh::TriMesh_ArrayKernelT<> Mesh;

int main(int argc, char **argv)
{
    if (argc != 4 || std::strcmp(argv[1], "loop") != 0) peer_usage(argv[0]);
    int levels = std::atoi(argv[3]);
    ObjData obj;
    if (!peer_read_obj(argv[2], obj)) { std::fprintf(stderr, "cannot read %s\n", argv[2]); return 1; }
    Mesh m;
    std::vector<Mesh::VertexHandle> vh;
    vh.reserve(obj.pos.size() / 3);
    for (size_t i = 0; i < obj.pos.size(); i += 3)
        vh.push_back(m.add_vertex(Mesh::Point((float)obj.pos[i], (float)obj.pos[i + 1], (float)obj.pos[i + 2])));
    std::vector<Mesh::VertexHandle> f;
    size_t c = 0, rejected = 0;
    for (size_t i = 0; i < obj.face_size.size(); ++i) {
        f.clear();
        for (int k = 0; k < obj.face_size[i]; ++k) f.push_back(vh[(size_t)obj.index[c++]]);
        if (!m.add_face(f).is_valid()) ++rejected;
    }
    if (rejected) std::fprintf(stderr, "warning: OpenMesh rejected %zu faces\n", rejected);
    std::vector<double>().swap(obj.pos);
    std::vector<int>().swap(obj.index);
    std::vector<int>().swap(obj.face_size);
    std::vector<Mesh::VertexHandle>().swap(vh);

    long rss_before = peer_rss_kb();
    double c0 = peer_cpu();
    double t0 = peer_now();
    OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
    loop.attach(m);
    loop(levels);
    loop.detach();
    double t1 = peer_now();
    double c1 = peer_cpu();
    peer_report("openmesh", "loop", argv[2], levels, (long)m.n_faces(), (long)m.n_vertices(),
                t1 - t0, c1 - c0, rss_before);
    return 0;
}
