// SPDX-License-Identifier: MIT
// Shared helpers of the peer drivers (bench/peers): a minimal OBJ reader (v and f records;
// f accepts v, v/vt, v//vn, v/vt/vn and negative indices), a monotonic clock, peak RSS, and
// the machine-readable result line. Not part of tinysubd.
#ifndef PEER_COMMON_HPP
#define PEER_COMMON_HPP
#include <sys/resource.h>
#include <time.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

struct ObjData {
    std::vector<double> pos;      // 3 per vertex
    std::vector<int> face_size;   // per face
    std::vector<int> index;       // 0-based, sum of face sizes
};

static bool peer_read_obj(const char *path, ObjData &o)
{
    FILE *f = std::fopen(path, "rb");
    if (!f) return false;
    char line[4096];
    while (std::fgets(line, sizeof line, f)) {
        char *p = line;
        while (*p == ' ' || *p == '\t') ++p;
        if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            char *e = p + 1;
            for (int k = 0; k < 3; ++k) o.pos.push_back(std::strtod(e, &e));
        } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            char *e = p + 1;
            int n = 0;
            for (;;) {
                while (*e == ' ' || *e == '\t') ++e;
                if (*e == '\0' || *e == '\n' || *e == '\r' || *e == '#') break;
                long v = std::strtol(e, &e, 10);
                while (*e && *e != ' ' && *e != '\t' && *e != '\n' && *e != '\r') ++e; // skip /vt/vn
                long nv = (long)(o.pos.size() / 3);
                o.index.push_back((int)(v < 0 ? nv + v : v - 1));
                ++n;
            }
            o.face_size.push_back(n);
        }
    }
    std::fclose(f);
    return !o.face_size.empty();
}

static double peer_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// CPU time of the process (user + system), for a machine shared with other jobs.
static double peer_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long peer_maxrss_kb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss; // kilobytes on Linux
}

// Current resident set (kB) from /proc/self/statm.
static long peer_rss_kb(void)
{
    long pages = 0, resident = 0;
    FILE *f = std::fopen("/proc/self/statm", "r");
    if (f) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return resident * 4; // 4 KiB pages
}

static std::string peer_mesh_name(const char *path)
{
    std::string s(path);
    size_t slash = s.find_last_of('/');
    if (slash != std::string::npos) s = s.substr(slash + 1);
    size_t dot = s.rfind('.');
    if (dot != std::string::npos) s = s.substr(0, dot);
    return s;
}

static void peer_usage(const char *argv0)
{
    std::fprintf(stderr, "usage: %s loop|doosabin MESH.obj LEVELS\n", argv0);
    std::exit(2);
}

static void peer_report(const char *peer, const char *scheme, const char *path, int levels,
                        long faces, long verts, double seconds, double cpu_seconds,
                        long rss_before_kb)
{
    std::printf("peer=%s scheme=%s mesh=%s level=%d faces=%ld verts=%ld wall_seconds=%.6f "
                "cpu_seconds=%.6f maxrss_kb=%ld rss_before_kb=%ld\n",
                peer, scheme, peer_mesh_name(path).c_str(), levels, faces, verts, seconds,
                cpu_seconds, peer_maxrss_kb(), rss_before_kb);
}
#endif
