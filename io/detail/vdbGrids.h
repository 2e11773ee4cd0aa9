#pragma once
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <openvdb/openvdb.h>

namespace solidtex::io::detail {

// Every grid of a .vdb with the file's metadata.
struct VdbContents {
  openvdb::GridPtrVec grids;
  openvdb::MetaMap::Ptr metadata;
  openvdb::GridPtrVec unread;  ///< the grids left out, with their metadata and empty trees
};

// Reads a whole .vdb at once: without delayed loading, damage is found while reading, not later
// when the grids are destroyed. Anything OpenVDB refuses, or memory a damaged size asks for, is
// one InputError naming the file, with OpenVDB's reason cut to a readable line; so is a grid, in a
// file writeVdbGrids wrote (its UUID says so), whose values no longer match their checksum.
// `only`: the names of the grids to read, those of them the file has; empty: every grid.
VdbContents readVdbGrids(const std::string& path, const std::vector<std::string>& only = {});

// The grid named `name`, or null.
openvdb::GridBase::Ptr findGrid(const VdbContents& contents, const std::string& name);

// OpenVDB's message about a damaged file, cut to printable words on one short line.
std::string readableReason(const std::string& what);

// Paints the 512 values of the leaf at `origin` in OpenVDB's order (z fastest).
using LeafPainter = std::function<void(const openvdb::Coord& origin, openvdb::Vec3s* values)>;

// Grids written together. A Vec3s grid whose tree has a painter holds only topology (leaves made
// with PartialCreate, no values): the writer paints its leaves a batch at a time, in parallel, and
// writes them, so its values are never all held. Such a file lacks only OpenVDB's delayed-loading
// hints for that grid (which would need the values before they are painted).
struct GridGroup {
  GridGroup(openvdb::GridPtrVec grids = {}) : grids(std::move(grids)) {}  // NOLINT: a plain group
  openvdb::GridPtrVec grids;
  std::map<const openvdb::TreeBase*, LeafPainter> painters;
};

// Makes one group of a file's grids when the writer reaches it, so that a large volume's grids are
// built, written and freed a group at a time. Grids sharing a tree belong to one group (the file
// stores the tree once); names must be unique and non-empty across the file.
using GridGroupMaker = std::function<GridGroup()>;

// Writes grid groups and file metadata to a .vdb (Blosc), the bytes OpenVDB's own writer gives for
// all the grids at once with each grid's valuesChecksum in its metadata (painted grids aside),
// checking every write: a full disk throws InputError, never leaves a truncated file behind a
// success. The header's UUID is hashed from the content, so the same grids give the same bytes. Commands
// write through OutputFiles, which puts the file in place only when all their outputs are written.
void writeVdbGrids(const std::string& path, const std::vector<GridGroupMaker>& groups,
                   const openvdb::MetaMap& meta = {});

// The same for grids already made: one group.
void writeVdbGrids(const std::string& path, const openvdb::GridPtrVec& grids,
                   const openvdb::MetaMap& meta = {});

}  // namespace solidtex::io::detail
