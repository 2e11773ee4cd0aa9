#pragma once
#include <string>

#include <openvdb/openvdb.h>

namespace solidtex {

/// Writes grids and file metadata to a .vdb (Blosc) through a temporary name beside `path`, then
/// renames it, so no partial file is ever left; the header's UUID is hashed from the content, so
/// the same grids give the same bytes. Throws InputError when the path cannot be written.
void writeVdbGrids(const std::string& path, const openvdb::GridPtrVec& grids,
                   const openvdb::MetaMap& meta = {});

}  // namespace solidtex
