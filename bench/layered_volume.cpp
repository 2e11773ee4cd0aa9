// A layered density volume: the exemplar of the frame-field previews in docs/methods.md. Bands along
// y (period 8 voxels) whose phase wanders slowly with x and z, plus a little noise, so that a
// synthesis has layers to turn and something to choose between.
// Usage: build/bench/layered_volume OUT.vdb [SIDE]
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>

#include "common/Random.h"
#include "io/vdbIO.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: layered_volume OUT.vdb [SIDE]\n";
    return 2;
  }
  const int side = argc > 2 ? std::atoi(argv[2]) : 48;
  solidtex::SolidVolume volume;
  volume.dims = {side, side, side};
  volume.density.resize(volume.dims.count());
  solidtex::Rng rng(7);
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const double phase =
            1.5 * std::sin(2 * std::numbers::pi * i / side) * std::cos(2 * std::numbers::pi * k / side);
        volume.density[volume.dims.index(i, j, k)] =
            float(0.5 + 0.4 * std::sin(2 * std::numbers::pi * j / 8 + phase) +
                  0.08 * (solidtex::uniform01(rng) - 0.5));
      }
  volume.metadata["exemplar"] = "layered_volume";
  solidtex::writeVdb(argv[1], std::move(volume));
  return 0;
}
