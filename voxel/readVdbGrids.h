#pragma once
#include <string>

#include <openvdb/openvdb.h>

namespace solidtex {

/// Every grid of a .vdb with the file's metadata.
struct VdbContents {
  openvdb::GridPtrVec grids;
  openvdb::MetaMap::Ptr metadata;
};

/// Reads a whole .vdb at once: without delayed loading, damage is found while reading, not later
/// when the grids are destroyed. Anything OpenVDB refuses, or memory a damaged size asks for, is
/// one InputError naming the file, with OpenVDB's reason cut to a readable line.
VdbContents readVdbGrids(const std::string& path);

/// The grid named `name`, or null.
openvdb::GridBase::Ptr findGrid(const VdbContents& contents, const std::string& name);

}  // namespace solidtex
