// embree_rays: Embree's side of the ray kernel benchmark (docs/speed.md, "Against Embree's kernel").
//
// Reads a scene's geometry as `studio-bench.jar kernel` writes it (WORK/NAME.kernel: world space,
// after our SceneCompiler; format in KernelGeometry.java) and traces what our engine traces there:
// for every pixel one camera ray through the pixel centre (rtcIntersect1, closest hit) and, where it
// hits, one shadow ray to the first light (rtcOccluded1). No shading. Spheres are Embree's
// RTC_GEOMETRY_TYPE_SPHERE_POINT, boxes and meshes triangles, a plane two triangles of half-size
// PLANE_HALF_SIZE. Scene flag RTC_SCENE_FLAG_ROBUST, build quality MEDIUM (Embree's default SAH
// build; --high for HIGH, which adds spatial splits). A warm-up frame, then --frames timed ones,
// each by the wall clock and by the tracing threads' CPU time. Prints one line in the form of the
// Java side (best and median frame, milliseconds and millions of rays a second), and writes each
// pixel's outcome beside FILE as NAME.embree.pgm (black: missed, white: lit, grey: in shadow), as
// the Java side writes NAME.ours.pgm.
//
//   embree_rays FILE [--threads 1] [--frames 15] [--high] [--verbose]

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

// A plane's two triangles reach this far from its point along both tangents: a ray that meets the
// infinite plane beyond it (in the scenes here: less than a hundredth of a pixel under the horizon) misses.
const double PLANE_HALF_SIZE = 1e5;

struct Geometry {
    int width = 0, height = 0;
    double camera[13] = {};  // position, right, up, backward, tan(fov / 2)
    double light[3] = {};
    std::vector<float> spheres;    // x y z r
    std::vector<float> vertices;   // x y z
    std::vector<unsigned> triangles;  // a b c
};

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "error: %s\n", message.c_str());
    std::exit(2);
}

void addPlane(Geometry& g, const double p[3], const double n[3]) {
    // two tangents: t = n x (the axis n is least along), b = n x t; exact for axis-aligned planes
    double a[3] = {0, 0, 0};
    int least = std::fabs(n[0]) <= std::fabs(n[1]) ? (std::fabs(n[0]) <= std::fabs(n[2]) ? 0 : 2)
                                                    : (std::fabs(n[1]) <= std::fabs(n[2]) ? 1 : 2);
    a[least] = 1;
    double t[3] = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]};
    double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (double& c : t) c /= tl;
    double b[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
    unsigned first = g.vertices.size() / 3;
    const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corners) {
        for (int k = 0; k < 3; k++) {
            g.vertices.push_back(float(p[k] + PLANE_HALF_SIZE * (c[0] * t[k] + c[1] * b[k])));
        }
    }
    unsigned quad[6] = {0, 1, 2, 0, 2, 3};
    for (unsigned i : quad) g.triangles.push_back(first + i);
}

Geometry read(const char* path) {
    std::ifstream in(path);
    if (!in) fail(std::string("cannot read ") + path);
    Geometry g;
    std::string word;
    while (in >> word) {
        if (word[0] == '#') {
            std::getline(in, word);
        } else if (word == "image") {
            in >> g.width >> g.height;
        } else if (word == "camera") {
            for (double& c : g.camera) in >> c;
        } else if (word == "light") {
            in >> g.light[0] >> g.light[1] >> g.light[2];
        } else if (word == "sphere") {
            double s[4];
            in >> s[0] >> s[1] >> s[2] >> s[3];
            for (double c : s) g.spheres.push_back(float(c));
        } else if (word == "plane") {
            double p[3], n[3];
            in >> p[0] >> p[1] >> p[2] >> n[0] >> n[1] >> n[2];
            addPlane(g, p, n);
        } else if (word == "triangles") {
            size_t v, t;
            in >> v >> t;
            unsigned first = g.vertices.size() / 3;
            for (size_t i = 0; i < 3 * v; i++) {
                double c;
                in >> c;
                g.vertices.push_back(float(c));
            }
            for (size_t i = 0; i < 3 * t; i++) {
                unsigned k;
                in >> k;
                g.triangles.push_back(first + k);
            }
        } else {
            fail(std::string("unknown record '") + word + "' in " + path);
        }
        if (!in) fail(std::string("malformed ") + path);
    }
    if (g.width <= 0 || g.height <= 0) fail(std::string("no image size in ") + path);
    return g;
}

RTCScene build(RTCDevice device, const Geometry& g, RTCBuildQuality quality) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, quality);
    if (!g.spheres.empty()) {
        RTCGeometry s = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        size_t n = g.spheres.size() / 4;
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(s, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), n));
        std::copy(g.spheres.begin(), g.spheres.end(), v);
        rtcSetGeometryBuildQuality(s, quality);
        rtcCommitGeometry(s);
        rtcAttachGeometry(scene, s);
        rtcReleaseGeometry(s);
    }
    if (!g.triangles.empty()) {
        RTCGeometry t = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(t, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), g.vertices.size() / 3));
        std::copy(g.vertices.begin(), g.vertices.end(), v);
        auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(t, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), g.triangles.size() / 3));
        std::copy(g.triangles.begin(), g.triangles.end(), i);
        rtcSetGeometryBuildQuality(t, quality);
        rtcCommitGeometry(t);
        rtcAttachGeometry(scene, t);
        rtcReleaseGeometry(t);
    }
    rtcCommitScene(scene);
    return scene;
}

struct Counts {
    long hits = 0, occluded = 0;
    double cpuMs = 0;  // the tracing thread's CPU time
};

double threadCpuMs() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

// Rows firstRow .. endRow - 1: a camera ray per pixel (as our Camera builds it, in double, then
// rounded to float), a shadow ray per hit from the hit point moved off the surface along the
// geometric normal, to the light's side, by SHADOW_OFFSET times the point's size (at least 1).
Counts trace(RTCScene scene, const Geometry& g, int firstRow, int endRow, unsigned char* mask) {
    // flush denormals to zero in this thread, as Embree asks of every thread that traces
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    const float SHADOW_OFFSET = 1e-4f;
    const double* c = g.camera;
    const double aspect = double(g.width) / g.height, tanHalf = c[12];
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    Counts counts;
    double cpuStart = threadCpuMs();
    for (int y = firstRow; y < endRow; y++) {
        double ndcY = 1 - 2 * (y + 0.5) / g.height;
        for (int x = 0; x < g.width; x++) {
            double ndcX = 2 * (x + 0.5) / g.width - 1;
            double sx = ndcX * tanHalf * aspect, sy = ndcY * tanHalf;
            double d[3];
            for (int k = 0; k < 3; k++) d[k] = sx * c[3 + k] + sy * c[6 + k] - c[9 + k];
            double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);

            RTCRayHit rh;
            rh.ray.org_x = float(c[0]); rh.ray.org_y = float(c[1]); rh.ray.org_z = float(c[2]);
            rh.ray.dir_x = float(d[0] / len); rh.ray.dir_y = float(d[1] / len); rh.ray.dir_z = float(d[2] / len);
            rh.ray.tnear = 0;
            rh.ray.tfar = INFINITY;
            rh.ray.time = 0;
            rh.ray.mask = ~0u;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &context, &rh);
            unsigned char& pixel = mask[size_t(y) * g.width + x];
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
                pixel = 0;
                continue;
            }
            counts.hits++;

            float p[3] = {rh.ray.org_x + rh.ray.tfar * rh.ray.dir_x, rh.ray.org_y + rh.ray.tfar * rh.ray.dir_y,
                          rh.ray.org_z + rh.ray.tfar * rh.ray.dir_z};
            float n[3] = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
            float nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            float toLight = 0;
            for (int k = 0; k < 3; k++) toLight += n[k] * (float(g.light[k]) - p[k]);
            float size = std::max({1.0f, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
            float offset = (toLight < 0 ? -SHADOW_OFFSET : SHADOW_OFFSET) * size / nl;
            float o[3], l[3];
            for (int k = 0; k < 3; k++) {
                o[k] = p[k] + offset * n[k];
                l[k] = float(g.light[k]) - o[k];
            }
            float dist = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);

            RTCRay shadow;
            shadow.org_x = o[0]; shadow.org_y = o[1]; shadow.org_z = o[2];
            shadow.dir_x = l[0] / dist; shadow.dir_y = l[1] / dist; shadow.dir_z = l[2] / dist;
            shadow.tnear = 0;
            shadow.tfar = dist;
            shadow.time = 0;
            shadow.mask = ~0u;
            shadow.id = 0;
            shadow.flags = 0;
            rtcOccluded1(scene, &context, &shadow);
            bool blocked = shadow.tfar < 0;  // Embree sets tfar to -inf when something blocks the ray
            counts.occluded += blocked;
            pixel = blocked ? 128 : 255;
        }
    }
    counts.cpuMs = threadCpuMs() - cpuStart;
    return counts;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) fail("usage: embree_rays FILE [--threads 1] [--frames 15] [--high] [--verbose]");
    int threads = 1, frames = 15;
    bool high = false, verbose = false;
    for (int i = 2; i < argc; i++) {
        std::string a = argv[i];
        if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (a == "--frames" && i + 1 < argc) frames = std::atoi(argv[++i]);
        else if (a == "--high") high = true;
        else if (a == "--verbose") verbose = true;
        else fail("unknown argument " + a);
    }
    if (threads < 1 || frames < 1) fail("--threads and --frames must be at least 1");

    Geometry g = read(argv[1]);
    RTCDevice device = rtcNewDevice(verbose ? "verbose=2" : nullptr);
    if (!device) fail("rtcNewDevice failed");
    RTCScene scene = build(device, g, high ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);

    // One frame: the rows in one band per thread; wall time, thread starts included.
    std::vector<unsigned char> mask(size_t(g.width) * g.height);
    auto frame = [&](Counts& total) {
        auto start = std::chrono::steady_clock::now();
        std::vector<Counts> bands(threads);
        if (threads == 1) {
            bands[0] = trace(scene, g, 0, g.height, mask.data());
        } else {
            std::vector<std::thread> pool;
            for (int i = 0; i < threads; i++) {
                pool.emplace_back([&, i] {
                    bands[i] = trace(scene, g, i * g.height / threads, (i + 1) * g.height / threads, mask.data());
                });
            }
            for (auto& t : pool) t.join();
        }
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        total = Counts();
        for (const Counts& b : bands) {
            total.hits += b.hits;
            total.occluded += b.occluded;
            total.cpuMs += b.cpuMs;
        }
        return ms;
    };

    Counts counts, again;
    double first = frame(counts);
    std::vector<double> times, cpu;
    for (int i = 0; i < frames; i++) {
        times.push_back(frame(again));
        cpu.push_back(again.cpuMs);
        if (again.hits != counts.hits || again.occluded != counts.occluded) fail("frames differ");
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        size_t n = v.size();
        return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    };
    double best = *std::min_element(times.begin(), times.end()), bestCpu = *std::min_element(cpu.begin(), cpu.end());

    std::string path = argv[1];
    std::string stem = path.substr(0, path.find_last_of('.'));
    std::string name = stem.substr(stem.find_last_of('/') + 1);
    std::ofstream pgm(stem + ".embree.pgm", std::ios::binary);
    pgm << "P5\n" << g.width << " " << g.height << "\n255\n";
    pgm.write(reinterpret_cast<const char*>(mask.data()), mask.size());
    if (!pgm) fail("cannot write " + stem + ".embree.pgm");
    long primary = long(g.width) * g.height, rays = primary + counts.hits;
    std::printf("kernel=embree scene=%s threads=%d primary=%ld shadow=%ld hits=%ld occluded=%ld "
                "first_ms=%.1f best_ms=%.1f median_ms=%.1f best_cpu_ms=%.1f median_cpu_ms=%.1f "
                "mrays_best=%.3f mrays_median=%.3f mrays_cpu_best=%.3f mrays_cpu_median=%.3f\n",
                name.c_str(), threads, primary, counts.hits, counts.hits, counts.occluded, first, best, median(times),
                bestCpu, median(cpu), rays / best / 1e3, rays / median(times) / 1e3, rays / bestCpu / 1e3,
                rays / median(cpu) / 1e3);
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return 0;
}
