// Primary-ray throughput of the raycast integrator through the whole host
// (render_image: tiles, sampler, camera rays, intersection, shading, film)
// against the same camera rays through a bare rtcIntersect1 loop on the same
// triangles, both on 2 threads. The target: raycast >= 0.7x bare.
// Command and latest numbers: bench/README.md.
//
//   build/bin/lancer_bench --benchmark_filter=RaycastOverBare --benchmark_repetitions=5
//
// The bare scenes are built with the same build quality as lancer's
// (kLancerBuildQuality mirrors embree_scene.cpp). BM_BareEmbreeRobustPrimaryRays
// is the bare loop with RTC_SCENE_FLAG_ROBUST, which lancer's scene sets for
// watertight meshes (render/src/geometry/watertight_test.cpp): the flag's own cost.
// BM_HostIntersectOnlyPrimaryRays runs the host with an integrator that only
// reports the hit the host found, to tell the host's and RenderScene's
// share from raycast's shading. BM_ScenePackets calls
// RenderScene::intersect_batch (coherent) on the packets without the host:
// Embree plus lancer's hit completion; the host's own share is the
// difference. BM_BarePackets traces the rays in 4x4-pixel packets
// (rtcIntersect16), as the host does for every camera batch: what Embree
// alone gains from coherence.
//
// Counters: Mrays/s for each; in BM_RaycastOverBareEmbree, measured in
// alternation in one process, `ratio` = raycast / bare and `ratio_robust` =
// raycast / bare-with-the-robust-flag. Memory: `scene_bytes_per_triangle`
// (resident set growth over compile_scene), `compile_peak_bytes_per_triangle`
// (peak resident set during compile above the level before it),
// `embree_bytes_per_triangle` (Embree's own allocations for the same
// triangles and flags, from rtcSetDeviceMemoryMonitorFunction) and
// `peak_bytes_per_triangle` (the whole process's peak, bare scenes included).
#include <sys/types.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/scene_graph.h"

namespace {

using namespace lancer;

constexpr int kGrid = 709;  // 2 * 708^2 = 1,002,528 triangles
constexpr int kWidth = 1024;
constexpr int kHeight = 768;
constexpr int kThreads = 2;
// What embree_scene.cpp builds lancer's scenes with; the bare loop gets the
// same, so the ratio compares traversal of equally good trees.
constexpr RTCBuildQuality kLancerBuildQuality = RTC_BUILD_QUALITY_MEDIUM;

// Embree's allocations on the bare device (bytes, net), from its memory monitor.
std::atomic<long long> g_embree_bytes{0};
bool count_embree_bytes(void*, ssize_t bytes, bool) {
    g_embree_bytes += bytes;
    return true;
}

void to_embree(const Ray& ray, RTCRay& out) {
    out.org_x = ray.origin.x;
    out.org_y = ray.origin.y;
    out.org_z = ray.origin.z;
    out.dir_x = ray.direction.x;
    out.dir_y = ray.direction.y;
    out.dir_z = ray.direction.z;
    out.tnear = ray.t_min;
    out.tfar = ray.t_max;
    out.time = 0.0f;
    out.mask = 0xFFFFFFFFu;
    out.id = 0;
    out.flags = 0;
}

// Resets the process's peak resident set (VmHWM) to the current one, so a
// later VmHWM is the peak of what follows. Linux >= 4.0; false elsewhere.
bool reset_peak_rss() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    return bool(clear);
}

// Wall and CPU (all threads of the process) seconds of one frame. On a
// shared, loaded machine the wall time mostly measures the scheduler; the
// CPU time measures the work, so ratios are given for both.
struct FrameTime {
    double wall = 0.0;
    double cpu = 0.0;
};

double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

class FrameClock {
  public:
    FrameTime stop() const {
        return {std::chrono::duration<double>(std::chrono::steady_clock::now() - m_wall).count(),
                process_cpu_seconds() - m_cpu};
    }

  private:
    std::chrono::steady_clock::time_point m_wall = std::chrono::steady_clock::now();
    double m_cpu = process_cpu_seconds();
};

// Kilobytes from /proc/self/status ("VmRSS:", "VmHWM:").
long status_kilobytes(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind(field, 0) == 0) return std::atol(line.c_str() + std::strlen(field));
    }
    return 0;
}

// A rippled height field over [-1,1]^2 in the xz plane, seen from above at
// an angle so every pixel's ray hits it and the BVH has real depth.
std::shared_ptr<sg::TriangleMesh> make_height_field() {
    auto mesh = std::make_shared<sg::TriangleMesh>();
    mesh->positions.reserve(std::size_t(kGrid) * kGrid);
    for (int j = 0; j < kGrid; ++j) {
        for (int i = 0; i < kGrid; ++i) {
            const double x = 2.0 * i / (kGrid - 1) - 1.0;
            const double z = 2.0 * j / (kGrid - 1) - 1.0;
            mesh->positions.emplace_back(x, 0.05 * std::sin(23.0 * x) * std::cos(17.0 * z), z);
        }
    }
    mesh->faces.reserve(std::size_t(2) * (kGrid - 1) * (kGrid - 1));
    for (int j = 0; j + 1 < kGrid; ++j) {
        for (int i = 0; i + 1 < kGrid; ++i) {
            const int a = j * kGrid + i, b = a + 1, c = a + kGrid, d = c + 1;
            sg::TriangleMesh::Face first, second;
            first.position[0] = a, first.position[1] = c, first.position[2] = b;
            second.position[0] = b, second.position[1] = c, second.position[2] = d;
            mesh->faces.push_back(first);
            mesh->faces.push_back(second);
        }
    }
    return mesh;
}

// The host's loop with the cheapest possible integrator: one scene.intersect
// per ray and nothing else. Separates the host's and RenderScene's own cost
// from raycast's shading.
class IntersectOnly final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit* hit, const RenderScene&, Sampler&) const override {
        return hit ? Color(1.0f) : Color(0.0f);
    }
    bool is_deterministic() const override { return true; }
};

struct BenchScene {
    std::shared_ptr<sg::TriangleMesh> mesh;
    std::unique_ptr<RenderScene> scene;
    Plugin plugin;
    std::unique_ptr<Integrator> raycast;
    std::vector<Ray> camera_rays;  // one per pixel centre, row-major
    std::unique_ptr<Film> film = std::make_unique<Film>(kWidth, kHeight);
    double rss_bytes_per_triangle = 0.0;
    double compile_peak_bytes_per_triangle = 0.0;
    double embree_bytes_per_triangle = 0.0;
    double compile_seconds = 0.0;

    RTCDevice device = nullptr;
    RTCScene bare_scene = nullptr;
    RTCScene bare_robust_scene = nullptr;  // same, with RTC_SCENE_FLAG_ROBUST as lancer's scene
    std::vector<float> vertices;           // xyz per vertex, padded for Embree's 16-byte loads
    std::vector<unsigned> indices;         // three per triangle

    std::size_t triangles() const { return mesh->faces.size(); }

    BenchScene() {
        mesh = make_height_field();
        sg::SceneGraph graph;
        sg::Camera camera;
        camera.location = sg::Vec3(0.0, 1.6, -1.3);
        const sg::Vec3 forward = glm::normalize(sg::Vec3(0.0, -1.6, 1.3));
        const sg::Vec3 right = glm::normalize(glm::cross(sg::Vec3(0.0, 1.0, 0.0), forward));
        camera.direction = forward;
        camera.right = right * (double(kWidth) / kHeight) * 0.7;
        camera.up = glm::cross(forward, right) * 0.7;
        graph.camera = camera;
        sg::Light light;
        light.position = sg::Vec3(2.0, 4.0, -3.0);
        graph.lights.push_back(light);
        sg::Object object;
        object.kind = sg::Object::Kind::Mesh;
        // The graph's own copy, which compiling moves into the render
        // scene; `mesh` stays whole for the bare Embree scenes.
        object.shape = sg::MeshRef(std::make_shared<sg::TriangleMesh>(*mesh));
        auto material = std::make_shared<sg::Material>();
        material->pigment.color.rgb = sg::Vec3(0.8);
        object.material = material;
        graph.objects.push_back(std::move(object));

        const bool peak_reset = reset_peak_rss();
        const long rss_before = status_kilobytes("VmRSS:");
        const auto compile_start = std::chrono::steady_clock::now();
        scene = compile_scene(std::move(graph));
        compile_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - compile_start).count();
        const long rss_after = status_kilobytes("VmRSS:");
        rss_bytes_per_triangle = 1024.0 * double(rss_after - rss_before) / double(triangles());
        if (peak_reset)
            compile_peak_bytes_per_triangle =
                1024.0 * double(status_kilobytes("VmHWM:") - rss_before) / double(triangles());

        plugin = load_plugin("raycast");
        raycast = plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, {}));
        raycast->prepare(*scene);

        camera_rays.reserve(std::size_t(kWidth) * kHeight);
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                scene->camera().generate_ray(x + 0.5f, y + 0.5f, kWidth, kHeight, camera_rays.emplace_back());
            }
        }
        build_bare_embree();
    }

    void build_bare_embree() {
        vertices.reserve(mesh->positions.size() * 3 + 1);
        for (const auto& p : mesh->positions) {
            vertices.push_back(float(p.x));
            vertices.push_back(float(p.y));
            vertices.push_back(float(p.z));
        }
        vertices.push_back(0.0f);
        for (const auto& face : mesh->faces) {
            for (int k = 0; k < 3; ++k) indices.push_back(unsigned(face.position[k]));
        }
        device = rtcNewDevice(nullptr);
        rtcSetDeviceMemoryMonitorFunction(device, count_embree_bytes, nullptr);
        bare_scene = make_bare_scene(RTC_SCENE_FLAG_NONE);
        // Built last, alone on the monitor's count: the flags lancer uses.
        const long long before = g_embree_bytes;
        bare_robust_scene = make_bare_scene(RTC_SCENE_FLAG_ROBUST);
        embree_bytes_per_triangle = double(g_embree_bytes - before) / double(triangles());
    }

    RTCScene make_bare_scene(RTCSceneFlags flags) {
        RTCScene bare = rtcNewScene(device);
        rtcSetSceneFlags(bare, flags);
        rtcSetSceneBuildQuality(bare, kLancerBuildQuality);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0,
                                   3 * sizeof(float), mesh->positions.size());
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices.data(), 0,
                                   3 * sizeof(unsigned), mesh->faces.size());
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(bare, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(bare);
        return bare;
    }

    ~BenchScene() {
        raycast.reset();  // before its plugin's code is unloaded
        if (bare_scene) rtcReleaseScene(bare_scene);
        if (bare_robust_scene) rtcReleaseScene(bare_robust_scene);
        if (device) rtcReleaseDevice(device);
    }

    // Seconds for one frame through the host with `integrator` (raycast by default).
    FrameTime render_raycast(const Integrator* integrator = nullptr) {
        RenderOptions options;
        options.width = kWidth;
        options.height = kHeight;
        options.threads = kThreads;
        options.progress = ProgressMode::Quiet;
        // A fresh film per frame, allocated (and its pages touched) outside
        // the timing: the progressive host plans each pixel's samples from
        // what the film already holds, so a film that has its one sample per
        // pixel would make the next frame render nothing.
        film = std::make_unique<Film>(kWidth, kHeight);
        const FrameClock clock;
        render_image(*scene, integrator ? *integrator : *raycast, options, *film);
        const FrameTime time = clock.stop();
        benchmark::DoNotOptimize(film->mean(kWidth / 2, kHeight / 2));
        return time;
    }

    // Times one frame of 16x16 tiles on kThreads threads; `trace_tile(tile,
    // context)` traces the tile's rays and returns how many hit. The total
    // goes to `hit_count` when given.
    template <typename TraceTile>
    FrameTime trace_tiles(TraceTile trace_tile, std::uint64_t* hit_count) const {
        tbb::task_arena arena(kThreads);
        std::atomic<std::uint64_t> hits{0};
        const FrameClock clock;
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range2d<int>(0, kHeight, 16, 0, kWidth, 16),
                              [&](const tbb::blocked_range2d<int>& tile) {
                                  hits.fetch_add(trace_tile(tile), std::memory_order_relaxed);
                              });
        });
        const FrameTime time = clock.stop();
        if (hit_count) *hit_count = hits;
        return time;
    }

    // Seconds for the same rays through rtcIntersect1 alone, same tiles and threads.
    // `hit_count`, when given, receives the number of rays that hit.
    FrameTime trace_bare(bool robust = false, std::uint64_t* hit_count = nullptr) const {
        const RTCScene target = robust ? bare_robust_scene : bare_scene;
        return trace_tiles(
            [&](const tbb::blocked_range2d<int>& tile) {
                RTCIntersectContext context;
                rtcInitIntersectContext(&context);
                std::uint64_t found = 0;
                for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                    for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                        RTCRayHit query;
                        to_embree(camera_rays[std::size_t(y) * kWidth + x], query.ray);
                        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(target, &context, &query);
                        found += query.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                    }
                return found;
            },
            hit_count);
    }

    // The same rays through RenderScene::intersect_batch in 4x4-pixel
    // blocks, 16 blocks to a call as the host gives them, hits completed, no
    // host: what lancer's scene adds to Embree.
    FrameTime trace_scene_packets() const {
        return trace_tiles(
            [&](const tbb::blocked_range2d<int>& tile) {
                constexpr int kBatch = 16 * 16;
                Ray rays[kBatch];
                Hit hits[kBatch];
                bool hit_found[kBatch];
                std::uint64_t found = 0;
                int count = 0;
                auto flush = [&] {
                    scene->intersect_batch(rays, count, hits, hit_found, RayCoherence::Coherent);
                    for (int k = 0; k < count; ++k) found += hit_found[k];
                    count = 0;
                };
                for (int y0 = tile.rows().begin(); y0 < tile.rows().end(); y0 += 4)
                    for (int x0 = tile.cols().begin(); x0 < tile.cols().end(); x0 += 4) {
                        for (int y = y0; y < std::min(y0 + 4, tile.rows().end()); ++y)
                            for (int x = x0; x < std::min(x0 + 4, tile.cols().end()); ++x)
                                rays[count++] = camera_rays[std::size_t(y) * kWidth + x];
                        if (count > kBatch - 16) flush();
                    }
                if (count > 0) flush();
                return found;
            },
            nullptr);
    }

    // The same rays in 4x4-pixel packets through rtcIntersect16: what
    // coherent camera rays cost Embree when traced together.
    FrameTime trace_bare_packets(bool robust) const {
        const RTCScene target = robust ? bare_robust_scene : bare_scene;
        return trace_tiles(
            [&](const tbb::blocked_range2d<int>& tile) {
                RTCIntersectContext context;
                rtcInitIntersectContext(&context);
                context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
                std::uint64_t found = 0;
                for (int y0 = tile.rows().begin(); y0 < tile.rows().end(); y0 += 4)
                    for (int x0 = tile.cols().begin(); x0 < tile.cols().end(); x0 += 4) {
                        alignas(64) RTCRayHit16 packet;
                        alignas(64) int valid[16];
                        for (int k = 0; k < 16; ++k) {
                            const int x = x0 + (k & 3), y = y0 + (k >> 2);
                            valid[k] = x < tile.cols().end() && y < tile.rows().end() ? -1 : 0;
                            RTCRay ray;
                            to_embree(
                                camera_rays[std::size_t(std::min(y, kHeight - 1)) * kWidth + std::min(x, kWidth - 1)],
                                ray);
                            packet.ray.org_x[k] = ray.org_x;
                            packet.ray.org_y[k] = ray.org_y;
                            packet.ray.org_z[k] = ray.org_z;
                            packet.ray.dir_x[k] = ray.dir_x;
                            packet.ray.dir_y[k] = ray.dir_y;
                            packet.ray.dir_z[k] = ray.dir_z;
                            packet.ray.tnear[k] = ray.tnear;
                            packet.ray.tfar[k] = ray.tfar;
                            packet.ray.time[k] = ray.time;
                            packet.ray.mask[k] = ray.mask;
                            packet.ray.id[k] = ray.id;
                            packet.ray.flags[k] = ray.flags;
                            packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                            packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                        }
                        rtcIntersect16(valid, target, &context, &packet);
                        for (int k = 0; k < 16; ++k)
                            found += valid[k] && packet.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
                    }
                return found;
            },
            nullptr);
    }
};

BenchScene& bench_scene() {
    static BenchScene scene;  // built once: compiling 1M triangles is not what is measured
    return scene;
}

constexpr double kRaysPerFrame = double(kWidth) * kHeight;

void set_common_counters(benchmark::State& state, const BenchScene& bench) {
    state.counters["triangles"] = double(bench.triangles());
    state.counters["scene_bytes_per_triangle"] = bench.rss_bytes_per_triangle;
    state.counters["compile_peak_bytes_per_triangle"] = bench.compile_peak_bytes_per_triangle;
    state.counters["embree_bytes_per_triangle"] = bench.embree_bytes_per_triangle;
    state.counters["compile_s"] = bench.compile_seconds;
    state.counters["peak_bytes_per_triangle"] = 1024.0 * double(status_kilobytes("VmHWM:")) / double(bench.triangles());
}

// Rays of the frame that find the height field in the robust scene but
// miss it without the flag: they slip through shared edges (watertightness,
// see embree_scene.cpp). The height field has no holes, so any such ray leaks.
void set_leak_counter(benchmark::State& state, const BenchScene& bench) {
    std::uint64_t fast_hits = 0, robust_hits = 0;
    bench.trace_bare(false, &fast_hits);
    bench.trace_bare(true, &robust_hits);
    state.counters["leaks_without_robust"] = double(robust_hits) - double(fast_hits);
}

// Times one frame per iteration with `trace_frame` and reports throughput
// per wall second and per CPU second (the latter steadier on a busy machine).
template <typename TraceFrame>
void time_primary_rays(benchmark::State& state, BenchScene& bench, TraceFrame trace_frame) {
    double seconds = 0.0, cpu_seconds = 0.0;
    for (auto _ : state) {
        const FrameTime frame = trace_frame();
        state.SetIterationTime(frame.wall);
        seconds += frame.wall;
        cpu_seconds += frame.cpu;
    }
    state.counters["Mrays/s"] = kRaysPerFrame * double(state.iterations()) / seconds / 1e6;
    state.counters["Mrays/cpu_s"] = kRaysPerFrame * double(state.iterations()) / cpu_seconds / 1e6;
    set_common_counters(state, bench);
}

void BM_RaycastPrimaryRays(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    time_primary_rays(state, bench, [&] { return bench.render_raycast(); });
}

void BM_BareEmbreePrimaryRays(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    time_primary_rays(state, bench, [&] { return bench.trace_bare(); });
}

void BM_BareEmbreeRobustPrimaryRays(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    time_primary_rays(state, bench, [&] { return bench.trace_bare(true); });
}

void BM_HostIntersectOnlyPrimaryRays(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    const IntersectOnly intersect_only;
    time_primary_rays(state, bench, [&] { return bench.render_raycast(&intersect_only); });
}

void BM_ScenePackets(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    time_primary_rays(state, bench, [&] { return bench.trace_scene_packets(); });
}

// All three in alternation, so drift in machine load hits them alike.
void BM_RaycastOverBareEmbree(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    FrameTime raycast, bare, robust;
    auto add = [](FrameTime& total, const FrameTime& frame) {
        total.wall += frame.wall;
        total.cpu += frame.cpu;
    };
    for (auto _ : state) {
        const FrameTime r = bench.render_raycast(), b = bench.trace_bare(), rb = bench.trace_bare(true);
        add(raycast, r);
        add(bare, b);
        add(robust, rb);
        state.SetIterationTime(r.wall + b.wall + rb.wall);
    }
    const double rays = kRaysPerFrame * double(state.iterations()) / 1e6;
    state.counters["raycast_Mrays/s"] = rays / raycast.wall;
    state.counters["bare_Mrays/s"] = rays / bare.wall;
    state.counters["bare_robust_Mrays/s"] = rays / robust.wall;
    state.counters["ratio"] = bare.wall / raycast.wall;
    state.counters["ratio_robust"] = robust.wall / raycast.wall;
    // The same from CPU time: what the ratio is on 2 idle cores.
    state.counters["raycast_Mrays/cpu_s"] = rays / raycast.cpu;
    state.counters["bare_Mrays/cpu_s"] = rays / bare.cpu;
    state.counters["ratio_cpu"] = bare.cpu / raycast.cpu;
    state.counters["ratio_robust_cpu"] = robust.cpu / raycast.cpu;
    set_common_counters(state, bench);
    set_leak_counter(state, bench);
}

// Arg 0: without, 1: with RTC_SCENE_FLAG_ROBUST.
void BM_BarePackets(benchmark::State& state) {
    BenchScene& bench = bench_scene();
    time_primary_rays(state, bench, [&] { return bench.trace_bare_packets(state.range(0) != 0); });
}
BENCHMARK(BM_BarePackets)->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_RaycastPrimaryRays)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BareEmbreePrimaryRays)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BareEmbreeRobustPrimaryRays)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_ScenePackets)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_HostIntersectOnlyPrimaryRays)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_RaycastOverBareEmbree)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(4.0);

}  // namespace

BENCHMARK_MAIN();
