#include "cli/commands.h"

namespace solidtex::cli {

void addExportOptions(CLI::App& command, VolumeExports& exports) {
  command.add_option("--tiff", exports.tiff,
                     "Folder for multi-page TIFF stacks (Fiji): color.tif, particle_id.tif, density.tif");
  command.add_option("--npy", exports.npy,
                     "Folder for numpy arrays: color.npy (Z,Y,X,3 float32), particle_id.npy (Z,Y,X int32), "
                     "density.npy");
  command.add_option("--vti", exports.vti, "VTK image data file (.vti, ParaView) with every grid");
}

}  // namespace solidtex::cli
