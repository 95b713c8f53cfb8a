// SPDX-License-Identifier: MIT
// CGAL (5.5, Subdivision_method_3) driver: DRIVER loop|doosabin MESH.obj LEVELS
// Surface_mesh<Simple_cartesian<double>::Point_3> built from the OBJ (untimed); timed: one call
// of Loop_subdivision / DooSabin_subdivision with number_of_iterations(LEVELS).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include "peer_common.hpp"

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

int main(int argc, char **argv)
{
    if (argc != 4) peer_usage(argv[0]);
    bool loop = std::strcmp(argv[1], "loop") == 0;
    if (!loop && std::strcmp(argv[1], "doosabin") != 0) peer_usage(argv[0]);
    int levels = std::atoi(argv[3]);
    ObjData obj;
    if (!peer_read_obj(argv[2], obj)) { std::fprintf(stderr, "cannot read %s\n", argv[2]); return 1; }
    Mesh m;
    std::vector<Mesh::Vertex_index> vh;
    vh.reserve(obj.pos.size() / 3);
    for (size_t i = 0; i < obj.pos.size(); i += 3)
        vh.push_back(m.add_vertex(Point(obj.pos[i], obj.pos[i + 1], obj.pos[i + 2])));
    std::vector<Mesh::Vertex_index> f;
    size_t c = 0, rejected = 0;
    for (size_t i = 0; i < obj.face_size.size(); ++i) {
        f.clear();
        for (int k = 0; k < obj.face_size[i]; ++k) f.push_back(vh[(size_t)obj.index[c++]]);
        if (m.add_face(f) == Mesh::null_face()) ++rejected;
    }
    if (rejected) std::fprintf(stderr, "warning: CGAL rejected %zu faces\n", rejected);
    std::vector<double>().swap(obj.pos);
    std::vector<int>().swap(obj.index);
    std::vector<int>().swap(obj.face_size);
    std::vector<Mesh::Vertex_index>().swap(vh);

    long rss_before = peer_rss_kb();
    double c0 = peer_cpu();
    double t0 = peer_now();
    if (loop)
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
    else
        CGAL::Subdivision_method_3::DooSabin_subdivision(m, CGAL::parameters::number_of_iterations(levels));
    double t1 = peer_now();
    double c1 = peer_cpu();
    peer_report("cgal", loop ? "loop" : "doosabin", argv[2], levels, (long)m.number_of_faces(),
                (long)m.number_of_vertices(), t1 - t0, c1 - c0, rss_before);
    return 0;
}
