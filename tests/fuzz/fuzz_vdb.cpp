// .vdb bytes -> readVdb, whole and as compare reads a particle solid (its ids, the box from the
// other grids' recorded bounds). A clean refusal (InputError) is the expected outcome for broken
// files; any other exception, crash, sanitizer report or out-of-memory is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/Error.h"
#include "inputFile.h"
#include "io/vdbIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static solidtex::fuzz::InputFile file("volume.vdb");
  const std::string& path = file.write(data, size);
  for (const solidtex::VdbReadOptions options :
       {solidtex::VdbReadOptions{}, solidtex::VdbReadOptions{false, false, true}})
    try {
      const solidtex::SolidVolume v = solidtex::readVdb(path, options);
      // The promise callers index by: each field is empty or holds one value per voxel.
      const auto fits = [&](const auto& field) { return field.empty() || field.size() == v.dims.count(); };
      if (!fits(v.density) || !fits(v.color) || !fits(v.particleId)) __builtin_trap();
    } catch (const solidtex::InputError&) {
    }
  return 0;
}
