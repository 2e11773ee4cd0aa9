#pragma once
#include <string>

#include <openvdb/openvdb.h>

namespace solidtex {

/// Writes grids and file metadata to a .vdb (Blosc), checking every write: a full disk throws
/// InputError, never leaves a truncated file behind a success. The header's UUID is hashed from
/// the content, so the same grids give the same bytes. Commands write through OutputFiles, which
/// puts the file in place only when all their outputs are written.
void writeVdbGrids(const std::string& path, const openvdb::GridPtrVec& grids,
                   const openvdb::MetaMap& meta = {});

}  // namespace solidtex
