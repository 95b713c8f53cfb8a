// SPDX-License-Identifier: MIT
// OpenSubdiv (3.5, Far API) Loop driver: DRIVER loop MESH.obj LEVELS
//                                      or DRIVER loop-obj MESH.obj LEVELS OUT.obj
// The standard uniform-refinement path of the Far tutorials: TopologyDescriptor ->
// TopologyRefinerFactory::Create (untimed, like building tinysubd's input mesh), then timed:
// RefineUniform(LEVELS) + PrimvarRefiner::Interpolate of the float xyz positions level by level
// into one buffer of all levels' vertices. Single-threaded (CPU, no OpenMP/TBB evaluator).
// loop-obj (the end-to-end row of run.sh, timed as a whole process from outside) also writes
// the last level as OBJ: "v x y z" with printf's "%.9g" (9 significant digits: the text reads
// back to the same float, as tinysubd's shortest text does) and "f a b c" (1-based), the
// Far tutorials' way of writing a level, through one stdio stream.
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/primvarRefiner.h>
#include "peer_common.hpp"

using namespace OpenSubdiv;

struct Vertex {
    float p[3];
    void Clear(void * = 0) { p[0] = p[1] = p[2] = 0.0f; }
    void AddWithWeight(Vertex const &s, float w)
    {
        p[0] += w * s.p[0];
        p[1] += w * s.p[1];
        p[2] += w * s.p[2];
    }
};

int main(int argc, char **argv)
{
    bool obj_out = argc == 5 && std::strcmp(argv[1], "loop-obj") == 0;
    if (!obj_out && (argc != 4 || std::strcmp(argv[1], "loop") != 0)) peer_usage(argv[0]);
    int levels = std::atoi(argv[3]);
    ObjData obj;
    if (!peer_read_obj(argv[2], obj)) { std::fprintf(stderr, "cannot read %s\n", argv[2]); return 1; }
    for (size_t i = 0; i < obj.face_size.size(); ++i)
        if (obj.face_size[i] != 3) { std::fprintf(stderr, "Loop needs triangles\n"); return 1; }

    typedef Far::TopologyDescriptor Descriptor;
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    Descriptor desc;
    desc.numVertices = (int)(obj.pos.size() / 3);
    desc.numFaces = (int)obj.face_size.size();
    desc.numVertsPerFace = obj.face_size.data();
    desc.vertIndicesPerFace = obj.index.data();
    Far::TopologyRefiner *refiner = Far::TopologyRefinerFactory<Descriptor>::Create(
        desc, Far::TopologyRefinerFactory<Descriptor>::Options(Sdc::SCHEME_LOOP, sdc));
    if (!refiner) { std::fprintf(stderr, "TopologyRefinerFactory failed\n"); return 1; }
    std::vector<float> base(obj.pos.begin(), obj.pos.end());
    std::vector<double>().swap(obj.pos);
    std::vector<int>().swap(obj.index);
    std::vector<int>().swap(obj.face_size);

    long rss_before = peer_rss_kb();
    double c0 = peer_cpu();
    double t0 = peer_now();
    Far::TopologyRefiner::UniformOptions uo(levels);
    uo.fullTopologyInLastLevel = false;
    refiner->RefineUniform(uo);
    std::vector<Vertex> vbuffer((size_t)refiner->GetNumVerticesTotal());
    std::memcpy(&vbuffer[0], base.data(), base.size() * sizeof(float));
    Vertex *src = &vbuffer[0];
    Far::PrimvarRefiner primvar(*refiner);
    for (int level = 1; level <= levels; ++level) {
        Vertex *dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    double t1 = peer_now();
    double c1 = peer_cpu();

    Far::TopologyLevel const &last = refiner->GetLevel(levels);
    double check = 0; // keep the result observable
    for (int i = 0; i < last.GetNumVertices(); i += 97) check += src[i].p[0];
    if (check != check) std::fprintf(stderr, "NaN in output\n");
    if (obj_out) {
        FILE *f = std::fopen(argv[4], "wb");
        if (!f) { std::fprintf(stderr, "cannot write %s\n", argv[4]); return 1; }
        std::fprintf(f, "# opensubdiv\n");
        for (int i = 0; i < last.GetNumVertices(); ++i)
            std::fprintf(f, "v %.9g %.9g %.9g\n", (double)src[i].p[0], (double)src[i].p[1], (double)src[i].p[2]);
        for (int i = 0; i < last.GetNumFaces(); ++i) {
            Far::ConstIndexArray fv = last.GetFaceVertices(i);
            std::fputc('f', f);
            for (int k = 0; k < fv.size(); ++k) std::fprintf(f, " %d", fv[k] + 1);
            std::fputc('\n', f);
        }
        if (std::fclose(f) != 0) { std::fprintf(stderr, "cannot write %s\n", argv[4]); return 1; }
    }
    peer_report("opensubdiv", obj_out ? "loop-obj" : "loop", argv[2], levels, last.GetNumFaces(), last.GetNumVertices(),
                t1 - t0, c1 - c0, rss_before);
    delete refiner;
    return 0;
}
