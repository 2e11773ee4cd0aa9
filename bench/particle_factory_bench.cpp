// Time to build a photo's pool of visual hulls and to make particles from them (rotate, size,
// voxelize), sharp and rounded, on 2 threads: the "shapes" share of a particle solid's time.
// Usage: particle_factory_bench [PHOTO]   (default data/particles/gravel.png)
#include <chrono>
#include <cstdio>
#include <string>

#include <tbb/global_control.h>

#include "particles/ParticleFactory.h"
#include "segmentation/analyzeExemplar.h"

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace solidtex;
  const std::string photo = argc > 1 ? argv[1] : std::string(SOLIDTEX_DATA_DIR) + "/particles/gravel.png";
  const ExemplarStats stats = analyzeExemplar(photo, SegmentationOptions{});
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  for (const double radius : {0.0, 0.04, 0.16}) {
    ParticleOptions options;
    options.smoothing.radius = radius;
    const auto start = std::chrono::steady_clock::now();
    const ParticleFactory factory(stats, options);
    const double poolMs = millisecondsSince(start);
    std::size_t triangles = 0;
    for (const HullMesh& h : factory.hulls()) triangles += h.triangles.size();
    std::printf("smoothing %.2f: pool of %zu hulls %.0f ms, %.0f triangles per hull\n", radius,
                factory.hulls().size(), poolMs, double(triangles) / double(factory.hulls().size()));
    for (const int side : {20, 60}) {
      Rng rng(1);
      const int count = side == 20 ? 2000 : 200;
      std::size_t voxels = 0;
      const auto makeStart = std::chrono::steady_clock::now();
      for (int i = 0; i < count; ++i) voxels += factory.make(side, side, side, rng).voxelCount();
      std::printf("  make %d^3: %.3f ms each, %.0f%% of the box filled\n", side,
                  millisecondsSince(makeStart) / count,
                  100.0 * double(voxels) / count / (side * side * side));
    }
  }
  return 0;
}
