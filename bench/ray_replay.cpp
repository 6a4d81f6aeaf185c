// The renderer against Embree alone on the renderer's own rays (issue 15):
//   bench_ray_replay --scene=FILE [--spp=N] [--threads=N] [--seed=S] [--max-rays=N]
//                    [--packets=4|8|16] [-D NAME=VALUE]...
// 1. renders the scene on the CPU backend and times it (no recording);
// 2. renders it again, same seed and threads, with an EmbreeScene RayRecorder that keeps every
//    closest-hit and shadow query per thread, in the order the thread traced them, with its
//    answer (48 bytes a ray; --max-rays caps the memory, 20 M rays = 960 MB by default);
// 3. traces the recorded queries again with rtcIntersect1 / rtcOccluded1 on the same RTCScene,
//    set up as EmbreeScene::intersect / occluded set them up, once comparing each answer with
//    the recorded one (a mismatch is an error: exit 1) and once timed.
// The replay runs on as many threads as the render, over chunks of consecutive rays of one
// thread's record, each chunk in its recorded order: the coherence the renderer had.
// --packets=N also replays them as Embree packets of N rays (rtcIntersectN / rtcOccludedN: what
// a wavefront renderer would trace), twice: each chunk's closest-hit and shadow queries apart
// in recorded order, and the same sorted by direction octant and origin (Morton order), a
// bound on the coherence that sorting a wavefront's rays could give; the sort is not timed.
// Scenes of meshes only (twinray's analytic shapes are user geometry written for one ray).
// Rays/s of the render over rays/s of the replay is the share of the render's time that
// traversal alone takes; it is reported over wall-clock and over process CPU time (the latter
// is what counts where other processes load the machine).
#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cpu_backend/embree_scene.h"
#include "cpu_backend/render_cpu.h"
#include "render/film_state.h"
#include "scenes/load_scene.h"

namespace {

using tr::Hit;
using tr::Ray;

constexpr std::uint32_t kClosest = 0;
constexpr std::uint32_t kShadow = 1;
constexpr size_t kChunk = 4096;  // rays of one thread's record replayed in order by one task

// One query and the renderer's answer: for a closest-hit query the hit's t, primitive and shape
// (NO_INDEX on a miss), for a shadow query `occluded` in `shape`.
struct RayRecord {
  Ray ray;
  float t;
  std::uint32_t primitive;
  std::uint32_t shape;
  std::uint32_t query;
};
static_assert(sizeof(RayRecord) == 48, "a record is the 32-byte ray and a 16-byte answer");

class Recorder final : public tr::RayRecorder {
 public:
  void scene_built(const tr::EmbreeScene& scene) override { scene_ = &scene; }
  void closest(const Ray& ray, const Hit& hit) override {
    rays_.local().push_back({ray, hit.t, hit.primitive, hit.shape, kClosest});
  }
  void shadow(const Ray& ray, bool occluded) override {
    rays_.local().push_back({ray, 0.0f, 0u, occluded ? 1u : 0u, kShadow});
  }

  const tr::EmbreeScene* scene() const { return scene_; }
  std::vector<const std::vector<RayRecord>*> per_thread() const {
    std::vector<const std::vector<RayRecord>*> out;
    for (const std::vector<RayRecord>& v : rays_)
      if (!v.empty()) out.push_back(&v);
    return out;
  }

 private:
  std::atomic<const tr::EmbreeScene*> scene_{nullptr};
  tbb::enumerable_thread_specific<std::vector<RayRecord>> rays_;
};

struct Chunk {
  const RayRecord* begin;
  const RayRecord* end;
};

// A closest-hit answer (hit or not, t, primitive) against the record: with kCheck 1 when it
// differs (t bit for bit), else a value the caller keeps so that the work is not optimized away.
template <bool kCheck>
std::uint64_t closest_answer(const RayRecord& r, bool hit, float t, std::uint32_t primitive) {
  if (!kCheck) return hit ? primitive : 0u;
  bool same = hit == (r.shape != tr::NO_INDEX);
  if (same && hit) same = std::memcmp(&t, &r.t, sizeof(float)) == 0 && primitive == r.primitive;
  return same ? 0u : 1u;
}

// The same for a shadow query's answer.
template <bool kCheck>
std::uint64_t shadow_answer(const RayRecord& r, bool occluded) {
  if (!kCheck) return occluded ? 1u : 0u;
  return occluded == (r.shape != 0u) ? 0u : 1u;
}

// Traces [c.begin, c.end) as EmbreeScene::intersect / occluded do; with kCheck,
// returns how many answers differ from the recorded ones (t bit for bit, primitive, hit or
// miss; occluded or not), else a value the caller keeps so that the work is not optimized away.
template <bool kCheck>
std::uint64_t replay(RTCScene scene, const Chunk& c) {
  std::uint64_t result = 0;
  for (const RayRecord* r = c.begin; r != c.end; ++r) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (r->query == kClosest) {
      RTCRayHit rh = tr::embree_ray_hit(r->ray);
      rtcIntersect1(scene, &context, &rh);
      result += closest_answer<kCheck>(*r, rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, rh.ray.tfar,
                                       rh.hit.primID);
    } else {
      RTCRay ray = tr::embree_ray(r->ray);
      rtcOccluded1(scene, &context, &ray);
      result += shadow_answer<kCheck>(*r, ray.tfar < 0.0f);
    }
  }
  return result;
}

// Embree's packet types and calls for N = 4, 8, 16.
template <class RayHitN, class RayN_, auto kIntersect, auto kOccluded>
struct PacketOf {
  using RayHit = RayHitN;
  using RayN = RayN_;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    kIntersect(v, s, c, r);
  }
  static void occluded(const int* v, RTCScene s, RTCIntersectContext* c, RayN* r) {
    kOccluded(v, s, c, r);
  }
};
template <int N>
struct Packet;
template <>
struct Packet<4> : PacketOf<RTCRayHit4, RTCRay4, rtcIntersect4, rtcOccluded4> {};
template <>
struct Packet<8> : PacketOf<RTCRayHit8, RTCRay8, rtcIntersect8, rtcOccluded8> {};
template <>
struct Packet<16> : PacketOf<RTCRayHit16, RTCRay16, rtcIntersect16, rtcOccluded16> {};

// Lane i of a packet ray from one recorded ray.
template <class RayN>
void set_lane(RayN& p, int i, const Ray& ray) {
  const RTCRay r = tr::embree_ray(ray);
  p.org_x[i] = r.org_x;
  p.org_y[i] = r.org_y;
  p.org_z[i] = r.org_z;
  p.tnear[i] = r.tnear;
  p.dir_x[i] = r.dir_x;
  p.dir_y[i] = r.dir_y;
  p.dir_z[i] = r.dir_z;
  p.time[i] = r.time;
  p.tfar[i] = r.tfar;
  p.mask[i] = r.mask;
  p.id[i] = r.id;
  p.flags[i] = r.flags;
}

// The records of one query kind, N at a time, as packets (the last one partly valid); with
// kCheck, how many answers differ from the recorded ones, else a value to keep.
template <int N, bool kCheck>
std::uint64_t replay_packets(RTCScene scene, const std::vector<const RayRecord*>& rays) {
  std::uint64_t result = 0;
  alignas(64) int valid[N];
  for (size_t first = 0; first < rays.size(); first += N) {
    const int lanes = int(std::min<size_t>(N, rays.size() - first));
    for (int i = 0; i < N; ++i) valid[i] = i < lanes ? -1 : 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (rays[first]->query == kClosest) {
      alignas(64) typename Packet<N>::RayHit rh;
      for (int i = 0; i < lanes; ++i) {
        set_lane(rh.ray, i, rays[first + i]->ray);
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      }
      Packet<N>::intersect(valid, scene, &context, &rh);
      for (int i = 0; i < lanes; ++i)
        result +=
            closest_answer<kCheck>(*rays[first + i], rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID,
                                   rh.ray.tfar[i], rh.hit.primID[i]);
    } else {
      alignas(64) typename Packet<N>::RayN ray;
      for (int i = 0; i < lanes; ++i) set_lane(ray, i, rays[first + i]->ray);
      Packet<N>::occluded(valid, scene, &context, &ray);
      for (int i = 0; i < lanes; ++i)
        result += shadow_answer<kCheck>(*rays[first + i], ray.tfar[i] < 0.0f);
    }
  }
  return result;
}

// 30 bits of Morton code of p within the scene's bounds [lo, hi].
std::uint32_t morton(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
  auto spread = [](std::uint32_t v) {  // 10 bits to every third bit
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    return (v | (v << 2)) & 0x09249249u;
  };
  const glm::vec3 u = glm::clamp((p - lo) / glm::max(hi - lo, glm::vec3(1e-20f)), 0.0f, 1.0f);
  return spread(std::uint32_t(u.x * 1023.0f)) << 2 | spread(std::uint32_t(u.y * 1023.0f)) << 1 |
         spread(std::uint32_t(u.z * 1023.0f));
}

// Each chunk's queries split by kind, in recorded order or sorted by (kind, direction octant,
// origin's Morton code): the packet replay's input, built before it is timed.
std::vector<std::vector<const RayRecord*>> packet_streams(const std::vector<Chunk>& chunks,
                                                          bool sorted, const RTCBounds& b) {
  const glm::vec3 lo(b.lower_x, b.lower_y, b.lower_z), hi(b.upper_x, b.upper_y, b.upper_z);
  std::vector<std::vector<const RayRecord*>> streams;
  for (const Chunk& c : chunks) {
    for (std::uint32_t kind : {kClosest, kShadow}) {
      std::vector<const RayRecord*> s;
      for (const RayRecord* r = c.begin; r != c.end; ++r)
        if (r->query == kind) s.push_back(r);
      if (sorted) {
        auto key = [&](const RayRecord* r) {
          const std::uint64_t octant =
              (r->ray.d.x < 0.0f) | (r->ray.d.y < 0.0f) << 1 | (r->ray.d.z < 0.0f) << 2;
          return octant << 32 | morton(r->ray.o, lo, hi);
        };
        std::stable_sort(s.begin(), s.end(),
                         [&](const RayRecord* a, const RayRecord* b) { return key(a) < key(b); });
      }
      if (!s.empty()) streams.push_back(std::move(s));
    }
  }
  return streams;
}

template <int N, bool kCheck>
std::uint64_t replay_all_packets(RTCScene scene,
                                 const std::vector<std::vector<const RayRecord*>>& streams) {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, streams.size(), 1), std::uint64_t(0),
      [&](const tbb::blocked_range<size_t>& range, std::uint64_t sum) {
        for (size_t i = range.begin(); i != range.end(); ++i)
          sum += replay_packets<N, kCheck>(scene, streams[i]);
        return sum;
      },
      [](std::uint64_t a, std::uint64_t b) { return a + b; });
}

// replay_all_packets for packets of n (4, 8 or 16) rays.
template <bool kCheck>
std::uint64_t packet_replay(std::uint32_t n, RTCScene scene,
                            const std::vector<std::vector<const RayRecord*>>& streams) {
  if (n == 4) return replay_all_packets<4, kCheck>(scene, streams);
  if (n == 8) return replay_all_packets<8, kCheck>(scene, streams);
  return replay_all_packets<16, kCheck>(scene, streams);
}

template <bool kCheck>
std::uint64_t replay_all(RTCScene scene, const std::vector<Chunk>& chunks) {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, chunks.size(), 1), std::uint64_t(0),
      [&](const tbb::blocked_range<size_t>& range, std::uint64_t sum) {
        for (size_t i = range.begin(); i != range.end(); ++i)
          sum += replay<kCheck>(scene, chunks[i]);
        return sum;
      },
      [](std::uint64_t a, std::uint64_t b) { return a + b; });
}

// Wall-clock and process CPU seconds (POSIX CLOCK_PROCESS_CPUTIME_ID: all of the process's
// threads). On a machine that other processes load, the CPU seconds are what this one was given.
struct Seconds {
  double wall = 0.0;
  double cpu = 0.0;
};

class Stopwatch {
 public:
  Stopwatch() : wall_(std::chrono::steady_clock::now()), cpu_(cpu_now()) {}
  Seconds elapsed() const {
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(),
            cpu_now() - cpu_};
  }

 private:
  static double cpu_now() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

struct TimedRender {
  std::unique_ptr<tr::Renderer> renderer;
  tr::FilmState film;
  Seconds seconds;  // the render alone: not the Embree build (make_cpu_renderer) nor the film
};

// Renders `spp` samples of every pixel, its EmbreeScene reporting to `recorder` (may be null).
TimedRender render(const tr::Scene& scene, const tr::RenderOptions& options, std::uint32_t spp,
                   Recorder* recorder) {
  TimedRender r;
  tr::EmbreeScene::record_new_scenes(recorder);
  try {
    r.renderer = tr::make_cpu_renderer(scene, options);
  } catch (...) {
    tr::EmbreeScene::record_new_scenes(nullptr);
    throw;
  }
  tr::EmbreeScene::record_new_scenes(nullptr);
  const tr::Camera& camera = scene.buffers.globals.camera;
  r.film = tr::empty_film(camera.width, camera.height, scene.buffers.globals.integrator.aov_count,
                          r.renderer->pass_size());
  Stopwatch watch;
  r.renderer->render(spp, r.film, {});
  r.seconds = watch.elapsed();
  return r;
}

struct Config {
  std::string scene;
  std::uint32_t spp = 0;
  std::uint32_t threads = 0;
  std::uint32_t seed = 0;
  std::uint64_t max_rays = 20000000;
  std::uint32_t packets = 0;  // 0: no packet replay
  tr::LoadOptions load;
};

std::uint64_t parse_count(const std::string& arg, const std::string& value) {
  size_t used = 0;
  unsigned long long v = 0;
  try {
    v = std::stoull(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size() || value[0] == '-')
    throw std::runtime_error("bench_ray_replay: " + arg + ": \"" + value +
                             "\" is not a non-negative integer");
  return v;
}

Config parse(int argc, char** argv) {
  Config c;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* prefix) {
      return a.rfind(prefix, 0) == 0 ? a.substr(std::strlen(prefix)) : std::string();
    };
    if (a.rfind("--scene=", 0) == 0) {
      c.scene = value("--scene=");
    } else if (a.rfind("--spp=", 0) == 0) {
      c.spp = std::uint32_t(parse_count("--spp", value("--spp=")));
    } else if (a.rfind("--threads=", 0) == 0) {
      c.threads = std::uint32_t(parse_count("--threads", value("--threads=")));
    } else if (a.rfind("--seed=", 0) == 0) {
      c.seed = std::uint32_t(parse_count("--seed", value("--seed=")));
    } else if (a.rfind("--max-rays=", 0) == 0) {
      c.max_rays = parse_count("--max-rays", value("--max-rays="));
    } else if (a.rfind("--packets=", 0) == 0) {
      c.packets = std::uint32_t(parse_count("--packets", value("--packets=")));
      if (c.packets != 4 && c.packets != 8 && c.packets != 16)
        throw std::runtime_error("bench_ray_replay: --packets must be 4, 8 or 16");
    } else if (a == "-D" && i + 1 < argc) {
      std::string kv = argv[++i];
      size_t eq = kv.find('=');
      c.load.defines[kv.substr(0, eq)] = eq == std::string::npos ? "" : kv.substr(eq + 1);
    } else {
      throw std::runtime_error("bench_ray_replay: unknown argument \"" + a + "\"");
    }
  }
  if (c.scene.empty()) throw std::runtime_error("bench_ray_replay: --scene=FILE is required");
  return c;
}

int run(const Config& config) {
  tr::Scene scene = tr::load_scene(config.scene, config.load);
  if (config.packets)
    for (const tr::Shape& shape : scene.buffers.shapes)
      if (shape.type != tr::SHAPE_MESH)
        throw std::runtime_error(
            "bench_ray_replay: --packets needs a scene of meshes only (its analytic shapes are "
            "Embree user geometry intersected one ray at a time)");
  const std::uint32_t spp = config.spp ? config.spp : scene.spp;
  const std::uint32_t threads =
      config.threads ? config.threads : std::uint32_t(tbb::info::default_concurrency());
  tr::RenderOptions options;
  options.spp = spp;
  options.seed = config.seed;
  options.threads = threads;

  // One CPU renderer at a time (make_cpu_renderer binds the scene for the process).
  std::uint64_t render_rays;
  Seconds render_seconds;
  {
    TimedRender plain = render(scene, options, spp, nullptr);
    render_rays = plain.film.stats.rays;
    render_seconds = plain.seconds;
  }
  if (render_rays > config.max_rays) {
    std::fprintf(stderr,
                 "bench_ray_replay: the render traces %llu rays, above --max-rays=%llu (48 bytes "
                 "a ray); lower --spp or the resolution, or raise the cap\n",
                 (unsigned long long)render_rays, (unsigned long long)config.max_rays);
    return 2;
  }
  Recorder recorder;
  TimedRender recorded_render = render(scene, options, spp, &recorder);
  const tr::FilmState& film = recorded_render.film;
  const tr::Camera& camera = scene.buffers.globals.camera;

  std::vector<Chunk> chunks;
  std::uint64_t recorded = 0, closest = 0;
  const auto per_thread = recorder.per_thread();
  for (const std::vector<RayRecord>* v : per_thread) {
    recorded += v->size();
    for (size_t i = 0; i < v->size(); i += kChunk)
      chunks.push_back({v->data() + i, v->data() + std::min(v->size(), i + kChunk)});
    for (const RayRecord& r : *v) closest += r.query == kClosest ? 1u : 0u;
  }
  if (recorded != render_rays || film.stats.rays != render_rays) {
    std::fprintf(stderr,
                 "bench_ray_replay: the recorded render traced %llu rays (%llu recorded), the "
                 "timed one %llu: the two renders are not the same\n",
                 (unsigned long long)film.stats.rays, (unsigned long long)recorded,
                 (unsigned long long)render_rays);
    return 1;
  }

  RTCScene rtc = recorder.scene()->rtc_scene();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const std::uint64_t mismatches = replay_all<true>(rtc, chunks);
  Stopwatch watch;
  const std::uint64_t keep = replay_all<false>(rtc, chunks);
  const Seconds replay_seconds = watch.elapsed();

  std::printf("scene       %s (%ux%u, %u spp, seed %u, %u thread%s, Embree %s)\n",
              config.scene.c_str(), camera.width, camera.height, spp, config.seed, threads,
              threads == 1 ? "" : "s", RTC_VERSION_STRING);
  std::printf("rays        %llu: %llu closest-hit, %llu shadow (%zu thread records, %.0f MB)\n",
              (unsigned long long)recorded, (unsigned long long)closest,
              (unsigned long long)(recorded - closest), per_thread.size(),
              double(recorded) * sizeof(RayRecord) * 1e-6);
  const double mrays = double(recorded) * 1e-6;
  auto row = [&](const char* name, const Seconds& t, const std::string& note) {
    std::printf("%-11s %9.3f %9.2f %9.3f %11.2f  %s\n", name, t.wall, mrays / t.wall, t.cpu,
                mrays / t.cpu, note.c_str());
  };
  std::printf("%-11s %9s %9s %9s %11s\n", "", "wall s", "Mrays/s", "CPU s", "Mrays/CPU-s");
  row("renderer", render_seconds, "");
  row("recording", recorded_render.seconds, "(the render recording its rays; not compared)");
  row("replay", replay_seconds,
      "(rtcIntersect1/rtcOccluded1 alone; checksum " + std::to_string(keep) + ")");
  std::printf("ratio       %.3f wall, %.3f CPU  (renderer rays/s / replay rays/s)\n",
              replay_seconds.wall / render_seconds.wall, replay_seconds.cpu / render_seconds.cpu);
  std::uint64_t packet_mismatches = 0;
  if (config.packets) {
    RTCBounds bounds;
    rtcGetSceneBounds(rtc, &bounds);
    for (bool sorted : {false, true}) {
      const auto streams = packet_streams(chunks, sorted, bounds);
      const std::uint64_t differ = packet_replay<true>(config.packets, rtc, streams);
      packet_mismatches += differ;
      Stopwatch packet_watch;
      const std::uint64_t kept = packet_replay<false>(config.packets, rtc, streams);
      const std::string name = "packets of " + std::to_string(config.packets);
      row(sorted ? "  sorted" : "packets", packet_watch.elapsed(),
          "(" + name + (sorted ? ", sorted by octant and origin" : ", in recorded order") + "; " +
              std::to_string(differ) + " answers differ; checksum " + std::to_string(kept) + ")");
    }
  }
  std::printf("mismatches  %llu  (replayed answers that differ from the recorded ones)\n",
              (unsigned long long)mismatches);
  if (mismatches + packet_mismatches != 0) {
    std::fprintf(stderr,
                 "bench_ray_replay: %llu replayed rays (%llu of them in packets) answer "
                 "differently than recorded\n",
                 (unsigned long long)(mismatches + packet_mismatches),
                 (unsigned long long)packet_mismatches);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
