#pragma once
/// @file
/// Volumes as multi-page TIFF stacks (one page per z slice), as Fiji/ImageJ opens them.

#include <string>

#include "common/Grid.h"
#include "common/VoxelSize.h"

namespace solidtex {

/// The sample type of a stack's pages.
enum class StackSample { UInt8, Int32, Float32 };

/// Writes `dims.z` pages of dims.x x dims.y pixels with `channels` samples each (x fastest, then
/// channel-interleaved, then y, then z: the order of a dense volume), uncompressed (what every reader takes),
/// with the voxel size as X/Y resolution (pixels per unit) and in the description. No ImageJ description: its
/// readers take an ImageJ stack's pages to be contiguous, which OpenImageIO's are not. Every page is read
/// back after writing. Throws InputError when the file cannot be written or is incomplete.
void writeTiffStack(const std::string& path, const Dims& dims, int channels, StackSample sample,
                    const void* data, const VoxelSize& voxelSize);

}  // namespace solidtex
