#include "io/BrickedVdb.h"

#include <sstream>
#include <utility>
#include <vector>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "common/Error.h"
#include "io/detail/solidGrids.h"
#include "io/detail/vdbGrids.h"

namespace solidtex {

struct BrickedVdb::Grids {
  double voxelSize = 1;
  openvdb::GridPtrVec grids;  // in the order writeVdb writes them; grids sharing a tree stay shared

  openvdb::GridBase::Ptr find(const std::string& name) const {
    for (const auto& grid : grids)
      if (grid->getName() == name) return grid;
    return nullptr;
  }

  // Bricks never overlap, so no voxel is active in both trees: OpenVDB moves the brick's leaves
  // over, and joins those a brick face cuts voxel by voxel.
  template <typename GridT>
  static bool mergeAs(openvdb::GridBase& into, openvdb::GridBase& from) {
    auto* a = dynamic_cast<GridT*>(&into);
    auto* b = dynamic_cast<GridT*>(&from);
    if (!a || !b) return false;
    a->tree().merge(b->tree(), openvdb::MERGE_ACTIVE_STATES);
    return true;
  }

  void merge(const openvdb::GridPtrVec& incoming) {
    std::map<const openvdb::TreeBase*, openvdb::GridBase::Ptr> oursByTree;
    for (const auto& grid : incoming) {
      const openvdb::TreeBase* tree = &grid->constBaseTree();
      auto ours = find(grid->getName());
      if (const auto shared = oursByTree.find(tree); shared != oursByTree.end()) {
        if (!ours) {  // another name for a tree (the colour's Cd): the same sharing in ours
          ours = shared->second->copyGrid();
          ours->setName(grid->getName());
          grids.push_back(ours);
        }
        continue;
      }
      if (!ours) {
        grids.push_back(grid);
      } else if (!mergeAs<openvdb::FloatGrid>(*ours, *grid) && !mergeAs<openvdb::Vec3SGrid>(*ours, *grid) &&
                 !mergeAs<openvdb::Int32Grid>(*ours, *grid)) {
        throw InputError("cannot join bricks: grid \"" + grid->getName() + "\" is " + grid->type() +
                         " in one and " + ours->type() + " in another");
      }
      oursByTree[tree] = ours ? ours : grid;
    }
  }
};

BrickedVdb::BrickedVdb(double voxelSize) : grids_(std::make_unique<Grids>()) {
  openvdb::initialize();
  grids_->voxelSize = voxelSize;
}
BrickedVdb::~BrickedVdb() = default;
BrickedVdb::BrickedVdb(BrickedVdb&&) noexcept = default;
BrickedVdb& BrickedVdb::operator=(BrickedVdb&&) noexcept = default;

void BrickedVdb::add(SolidVolume brick) {
  openvdb::GridPtrVec grids;
  for (const auto& makeGroup : io::detail::gridGroupsOf(brick, grids_->voxelSize)) {
    const io::detail::GridGroup group = makeGroup();
    if (!group.painters.empty())
      throw std::logic_error("BrickedVdb: colours painted from particle ids are not joined in bricks");
    grids.insert(grids.end(), group.grids.begin(), group.grids.end());
  }
  grids_->merge(grids);
}

std::string BrickedVdb::bytes() const {
  std::ostringstream out(std::ios::binary);
  openvdb::io::Stream stream(out);
  stream.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  stream.write(grids_->grids);
  return std::move(out).str();
}

void BrickedVdb::addBytes(const std::string& bytes) {
  std::istringstream in(bytes, std::ios::binary);
  openvdb::GridPtrVecPtr grids;
  try {
    // Loaded now, not delayed: a delayed load maps a temporary copy that the leaves would read
    // after this stream has gone.
    openvdb::io::Stream stream(in, /*delayLoad=*/false);
    grids = stream.getGrids();
  } catch (const openvdb::Exception& e) {
    throw InputError("cannot join bricks: " + io::detail::readableReason(e.what()));
  }
  grids_->merge(*grids);
}

namespace {

template <typename GridT, typename Value>
void copyBox(const openvdb::GridBase::Ptr& grid, const openvdb::CoordBBox& box, std::vector<Value>& out) {
  const auto typed = openvdb::gridConstPtrCast<GridT>(grid);
  if (!typed) return;
  out.assign(box.volume(), Value{});
  openvdb::tools::Dense<typename GridT::ValueType, openvdb::tools::LayoutXYZ> dense(
      box, reinterpret_cast<typename GridT::ValueType*>(out.data()));
  openvdb::tools::copyToDense(*typed, dense);
}

}  // namespace

SolidVolume BrickedVdb::denseBox(const Box& box) const {
  SolidVolume out;
  out.dims = box.dims();
  out.origin = box.lo;
  const openvdb::CoordBBox bbox(openvdb::Coord(box.lo.x, box.lo.y, box.lo.z),
                                openvdb::Coord(box.hi.x - 1, box.hi.y - 1, box.hi.z - 1));
  copyBox<openvdb::Vec3SGrid>(grids_->find("color"), bbox, out.color);
  copyBox<openvdb::FloatGrid>(grids_->find("density"), bbox, out.density);
  return out;
}

void BrickedVdb::write(const std::string& path, const std::map<std::string, std::string>& metadata) {
  openvdb::MetaMap meta;
  for (const auto& [key, value] : metadata) meta.insertMeta(key, openvdb::StringMetadata(value));
  io::detail::writeVdbGrids(path, grids_->grids, meta);
}

}  // namespace solidtex
