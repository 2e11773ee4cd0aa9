#pragma once
/// @file BrickedVdb.h
/// @brief A .vdb made of bricks computed apart, by one process or by many: the bytes writeVdb gives
/// for the whole volume.
#include <map>
#include <memory>
#include <string>

#include "common/Box.h"
#include "common/SolidVolume.h"

namespace solidtex {

/// The grids of the bricks added so far, each brick at its place in the whole volume's index space
/// (its SolidVolume::origin). Bricks must not overlap. For grids that keep every voxel of the box
/// active (colours, a density volume's values, sources: what volume synthesis writes), write()
/// gives the file writeVdb gives for the whole volume once all bricks are added, in whatever order
/// and by whatever process they came. Grids whose constant parts writeVdb turns into tiles
/// (particle ids, a density beside colours) keep each brick's tiles instead.
class BrickedVdb {
public:
  explicit BrickedVdb(double voxelSize = 1.0);
  ~BrickedVdb();
  BrickedVdb(BrickedVdb&&) noexcept;
  BrickedVdb& operator=(BrickedVdb&&) noexcept;

  /// Adds a brick's voxels, consuming its dense arrays.
  void add(SolidVolume brick);
  /// The bricks added so far as bytes (an OpenVDB stream), for another process's addBytes.
  std::string bytes() const;
  /// Adds the bricks `bytes` (from bytes()) hold. Throws InputError when they are no OpenVDB stream.
  void addBytes(const std::string& bytes);
  /// The voxels of `box` in dense form: colour and density as writeVdb was given them, origin box.lo.
  SolidVolume denseBox(const Box& box) const;
  /// Writes every brick added as one .vdb with the file's metadata. Throws InputError when the path
  /// cannot be written.
  void write(const std::string& path, const std::map<std::string, std::string>& metadata);

private:
  struct Grids;
  std::unique_ptr<Grids> grids_;
};

}  // namespace solidtex
