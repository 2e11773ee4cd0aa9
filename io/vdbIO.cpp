#include "io/vdbIO.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>
#include <system_error>
#include <vector>

#include <sys/mman.h>
#include <unistd.h>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "io/detail/solidGrids.h"
#include "io/detail/vdbGrids.h"

namespace solidtex {
namespace {

static_assert(sizeof(Rgb) == sizeof(openvdb::Vec3s), "Rgb must be layout-compatible with Vec3s");

openvdb::CoordBBox boxOf(const Dims& dims, const openvdb::Coord& origin = {}) {
  return openvdb::CoordBBox(origin, origin + openvdb::Coord(dims.x - 1, dims.y - 1, dims.z - 1));
}

openvdb::Coord originOf(const SolidVolume& volume) {
  return {volume.origin.x, volume.origin.y, volume.origin.z};
}

template <typename T>
void release(std::vector<T>& data) {
  std::vector<T>().swap(data);
}

// Hands the whole pages of [begin, end) back to the system; they read as zeros if touched again.
void releasePages(const void* begin, const void* end) {
  const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  const std::uintptr_t from = (std::uintptr_t(begin) + page - 1) / page * page;
  const std::uintptr_t to = std::uintptr_t(end) / page * page;
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
}

// A grid of the dense data, which it consumes, its first voxel at index `origin`: built one slab of leaves (8
// z-layers, contiguous in our layout) at a time, each slab's memory going back to the system once its leaves
// are built, so that a volume's array and its grid are never both held whole.
template <typename GridT, typename Value>
typename GridT::Ptr sparseFrom(const Dims& dims, const openvdb::Coord& origin, std::vector<Value>& data,
                               const typename GridT::ValueType& tolerance, const std::string& name,
                               const openvdb::math::Transform::Ptr& xform) {
  using VdbValue = typename GridT::ValueType;
  static_assert(sizeof(VdbValue) == sizeof(Value));
  auto grid = GridT::create(VdbValue(openvdb::zeroVal<VdbValue>()));
  constexpr int kSlab = int(GridT::TreeType::LeafNodeType::DIM);
  const std::size_t layer = std::size_t(dims.x) * std::size_t(dims.y);
  for (int z = 0; z < dims.z; z += kSlab) {
    const int depth = std::min(kSlab, dims.z - z);
    Value* first = data.data() + std::size_t(z) * layer;
    const openvdb::CoordBBox slab(origin + openvdb::Coord(0, 0, z),
                                  origin + openvdb::Coord(dims.x - 1, dims.y - 1, z + depth - 1));
    openvdb::tools::Dense<VdbValue, openvdb::tools::LayoutXYZ> dense(slab,
                                                                     reinterpret_cast<VdbValue*>(first));
    openvdb::tools::copyFromDense(dense, *grid, tolerance);
    releasePages(first, first + std::size_t(depth) * layer);
  }
  release(data);
  grid->setName(name);
  grid->setTransform(xform);
  return grid;
}

// density: the volume's own, or 1 on the particles (the active voxels of `ids`), or 1 everywhere.
// Without colour the density is the content (a solid from a density volume): every voxel stays
// active, zeros included, so the file keeps its box.
openvdb::FloatGrid::Ptr densityGrid(SolidVolume& volume, bool hasColor, const openvdb::Int32Grid::Ptr& ids,
                                    const openvdb::math::Transform::Ptr& xform) {
  openvdb::FloatGrid::Ptr grid;
  if (!volume.density.empty()) {
    const float tolerance = hasColor ? 0.f : -1.f;
    grid = sparseFrom<openvdb::FloatGrid>(volume.dims, originOf(volume), volume.density, tolerance, "density",
                                          xform);
  } else if (ids) {
    grid = openvdb::FloatGrid::create(
        std::make_shared<openvdb::FloatTree>(ids->tree(), 0.f, 1.f, openvdb::TopologyCopy()));
  } else {
    grid = openvdb::FloatGrid::create(0.f);
    grid->denseFill(boxOf(volume.dims, originOf(volume)), 1.f, true);
  }
  grid->setName("density");
  grid->setTransform(xform);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  return grid;
}

// The colour grid's topology, every voxel of the box active, in leaves that hold no values.
openvdb::Vec3SGrid::Ptr activeBoxTopology(const openvdb::CoordBBox& box) {
  using Leaf = openvdb::Vec3STree::LeafNodeType;
  auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.f));
  const int mask = ~int(Leaf::DIM - 1);  // a leaf's first voxel, below the box's when not aligned
  const openvdb::Coord first(box.min().x() & mask, box.min().y() & mask, box.min().z() & mask);
  for (int z = first.z(); z <= box.max().z(); z += int(Leaf::DIM))
    for (int y = first.y(); y <= box.max().y(); y += int(Leaf::DIM))
      for (int x = first.x(); x <= box.max().x(); x += int(Leaf::DIM)) {
        auto leaf = std::make_unique<Leaf>(openvdb::PartialCreate(), openvdb::Coord(x, y, z));
        for (openvdb::Index n = 0; n < Leaf::SIZE; ++n)
          if (box.isInside(leaf->offsetToGlobalCoord(n))) leaf->setValueOn(n);
        grid->tree().addLeaf(leaf.release());
      }
  return grid;
}

// A negative tolerance keeps every voxel active: colour must cover the whole box, black included.
// Colours painted on demand are painted leaf by leaf as they are written, from the dense ids.
io::detail::GridGroup colorGrids(SolidVolume& volume, const openvdb::math::Transform::Ptr& xform) {
  io::detail::GridGroup group;
  openvdb::Vec3SGrid::Ptr color;
  if (!volume.color.empty()) {
    color = sparseFrom<openvdb::Vec3SGrid>(volume.dims, originOf(volume), volume.color, openvdb::Vec3s(-1.f),
                                           "color", xform);
  } else {
    color = activeBoxTopology(boxOf(volume.dims, originOf(volume)));
    group.painters[&color->tree()] = [&volume](const openvdb::Coord& origin, openvdb::Vec3s* values) {
      for (openvdb::Index n = 0; n < openvdb::Vec3STree::LeafNodeType::SIZE; ++n) {
        const openvdb::Coord c =
            origin - originOf(volume) + openvdb::Vec3STree::LeafNodeType::offsetToLocalCoord(n);
        const bool inside = volume.dims.contains(c.x(), c.y(), c.z());
        const Rgb rgb = inside ? volume.colorAt(c.x(), c.y(), c.z()) : Rgb{0.f, 0.f, 0.f};
        values[n] = openvdb::Vec3s(rgb[0], rgb[1], rgb[2]);
      }
    };
    color->setName("color");
    color->setTransform(xform);
  }
  color->setVectorType(openvdb::VEC_INVARIANT);
  auto cd = color->copyGrid();  // shares the tree: Houdini's name for the same data
  cd->setName("Cd");
  group.grids = {color, cd};
  return group;
}

// The particles' voxels (the ids' active ones) hold their phase + 1; the matrix is inactive 0.
openvdb::Int32Grid::Ptr phaseGridOf(const openvdb::Int32Grid& ids, const std::vector<std::uint8_t>& phaseOf) {
  auto phase = ids.deepCopy();
  phase->setName("phase");
  for (auto it = phase->tree().beginValueOn(); it; ++it) {
    const std::int32_t id = *it;
    it.setValue(id > 0 && std::size_t(id) <= phaseOf.size() ? phaseOf[std::size_t(id) - 1] + 1 : 0);
  }
  return phase;
}

openvdb::GridPtrVec densityAndIdGrids(SolidVolume& volume, bool hasColor,
                                      const openvdb::math::Transform::Ptr& xform) {
  openvdb::Int32Grid::Ptr ids;
  if (!volume.particleId.empty())
    ids = sparseFrom<openvdb::Int32Grid>(volume.dims, originOf(volume), volume.particleId, 0, "particle_id",
                                         xform);
  auto density = densityGrid(volume, hasColor, ids, xform);
  if (!ids) return {density};
  if (volume.particlePhase.empty()) return {density, ids};
  return {density, ids, phaseGridOf(*ids, volume.particlePhase)};
}

}  // namespace

// The grids in groups, each consuming its dense arrays when the writer reaches it and freed once
// written. Colour goes first, beside only the dense ids (4 bytes a voxel): its tree (12 bytes a voxel
// when the colours are dense, topology only when they are painted as written), and the ids' and
// density's trees come after it is gone. A region of a larger volume keeps the larger volume's
// index space, so that OpenVDB joins the regions' trees voxel by voxel.
std::vector<io::detail::GridGroupMaker> io::detail::gridGroupsOf(SolidVolume& volume, double voxelSize) {
  auto xform = openvdb::math::Transform::createLinearTransform(voxelSize);
  std::vector<io::detail::GridGroupMaker> groups;
  const bool hasColor = volume.hasColor();
  if (hasColor) groups.push_back([&volume, xform] { return colorGrids(volume, xform); });
  groups.push_back([&volume, hasColor, xform] { return densityAndIdGrids(volume, hasColor, xform); });
  if (!volume.sourcePosition.empty())
    groups.push_back([&volume, xform] {
      std::vector<Rgb> positions(volume.sourcePosition.size());
      for (std::size_t i = 0; i < positions.size(); ++i)
        positions[i] = {volume.sourcePosition[i][0], volume.sourcePosition[i][1], 0.f};
      release(volume.sourcePosition);
      return openvdb::GridPtrVec{sparseFrom<openvdb::Vec3SGrid>(
          volume.dims, originOf(volume), positions, openvdb::Vec3s(-1.f), "source_position", xform)};
    });
  if (!volume.sourceVoxel.empty())
    groups.push_back([&volume, xform] {
      return openvdb::GridPtrVec{sparseFrom<openvdb::Vec3SGrid>(
          volume.dims, originOf(volume), volume.sourceVoxel, openvdb::Vec3s(-1.f), "source", xform)};
    });
  return groups;
}

void writeVdb(const std::string& path, SolidVolume volume, double voxelSize) {
  openvdb::initialize();
  if (volume.coloring && volume.color.empty()) {
    if (volume.particleId.size() != volume.dims.count())
      throw std::logic_error("writeVdb: colours are painted from the particle ids, which it lacks");
  } else if ((!volume.color.empty() || volume.density.empty()) &&
             volume.color.size() != volume.dims.count()) {
    throw std::logic_error("writeVdb: colour grid does not match the volume's dimensions");
  }
  // The grids consume their arrays slab by slab, handing pages back: a short one would lose others' data.
  for (const std::size_t size : {volume.density.size(), volume.particleId.size(),
                                 volume.sourcePosition.size(), volume.sourceVoxel.size()})
    if (size != 0 && size != volume.dims.count())
      throw std::logic_error("writeVdb: a grid does not match the volume's dimensions");
  openvdb::MetaMap meta;
  for (const auto& [key, value] : volume.metadata) meta.insertMeta(key, openvdb::StringMetadata(value));
  io::detail::writeVdbGrids(path, io::detail::gridGroupsOf(volume, voxelSize), meta);
}

namespace {

template <typename GridT, typename Value>
void denseFrom(const GridT& grid, const openvdb::CoordBBox& box, std::vector<Value>& out) {
  out.assign(box.volume(), Value{});
  openvdb::tools::Dense<typename GridT::ValueType, openvdb::tools::LayoutXYZ> dense(
      box, reinterpret_cast<typename GridT::ValueType*>(out.data()));
  openvdb::tools::copyToDense(grid, dense);
}

// NaN or infinite colours and densities would travel silently through every measure.
void checkValues(const std::string& path, const SolidVolume& volume) {
  const auto finite = [](float v) { return std::isfinite(v); };
  if (!std::all_of(volume.density.begin(), volume.density.end(), finite))
    throw InputError("cannot read " + path + ": its density grid holds NaN or infinite values");
  for (const Rgb& c : volume.color)
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
      throw InputError("cannot read " + path + ": its color grid holds NaN or infinite values");
  if (std::any_of(volume.particleId.begin(), volume.particleId.end(), [](std::int32_t id) { return id < 0; }))
    throw InputError("cannot read " + path + ": its particle_id grid holds negative ids");
}

// Every method reads a volume as cubes on its index axes: other voxels would be silently distorted.
void checkCubicVoxels(const std::string& path, const openvdb::GridBase& grid) {
  const openvdb::math::MapBase& map = *grid.transform().baseMap();
  const bool axisAligned =
      map.isType<openvdb::math::UniformScaleMap>() || map.isType<openvdb::math::UniformScaleTranslateMap>() ||
      map.isType<openvdb::math::ScaleMap>() || map.isType<openvdb::math::ScaleTranslateMap>() ||
      map.isType<openvdb::math::TranslationMap>();
  const openvdb::Vec3d size = grid.voxelSize();
  const double tolerance = 1e-6 * size.x();
  if (axisAligned && std::abs(size.y() - size.x()) <= tolerance && std::abs(size.z() - size.x()) <= tolerance)
    return;
  char sides[96];
  std::snprintf(sides, sizeof sides, "%g x %g x %g", size.x(), size.y(), size.z());
  throw InputError(
      "cannot read " + path + ": grid \"" + grid.getName() + "\" has " +
      (axisAligned ? std::string("voxels of ") + sides : std::string("voxels turned against its axes")) +
      "; resample it to cubic, axis-aligned voxels first");
}

template <typename GridT>
typename GridT::Ptr typedGrid(const io::detail::VdbContents& contents, const std::string& path,
                              const std::string& name, const char* type) {
  const auto grid = io::detail::findGrid(contents, name);
  if (!grid) return nullptr;
  auto typed = openvdb::gridPtrCast<GridT>(grid);
  if (!typed)
    throw InputError("cannot read " + path + ": grid \"" + name + "\" is " +
                     io::detail::readableReason(grid->type()) + ", not " + type);
  checkCubicVoxels(path, *typed);
  return typed;
}

// The dense box must be one a volume can have and memory can hold: a damaged file can claim any.
void checkBox(const std::string& path, const openvdb::CoordBBox& box, std::size_t bytesPerVoxel) {
  constexpr std::int64_t kLongestSide = 32768;
  // In 64 bits: a box from -2^30 to 2^30 would overflow dim()'s int32 to a negative side.
  const auto side = [&](int axis) { return std::int64_t(box.max()[axis]) - box.min()[axis] + 1; };
  const std::int64_t x = side(0), y = side(1), z = side(2);
  const std::string sides = std::to_string(x) + "x" + std::to_string(y) + "x" + std::to_string(z);
  if (std::min({x, y, z}) < 1 || std::max({x, y, z}) > kLongestSide)
    throw InputError("cannot read " + path + ": its grids span " + sides + " voxels, not 1 to " +
                     std::to_string(kLongestSide) + " on a side");
  requireMemory("reading " + path + " (" + sides + " voxels)",
                double(x) * double(y) * double(z) * double(bytesPerVoxel));
}

openvdb::GridBase::Ptr unreadGrid(const io::detail::VdbContents& contents, const std::string& name) {
  for (const auto& grid : contents.unread)
    if (grid->getName() == name) return grid;
  return nullptr;
}

// What a grid's writer recorded of it (OpenVDB's file statistics), for a grid not read: the first
// grid of that name, as findGrid takes it.
template <typename T>
std::optional<T> recorded(const io::detail::VdbContents& contents, const std::string& name,
                          const std::string& key) {
  const auto grid = unreadGrid(contents, name);
  if (!grid) return std::nullopt;
  if (const auto meta = grid->getMetadata<openvdb::TypedMetadata<T>>(key)) return meta->value();
  return std::nullopt;
}

// The active box of a grid, from its tree or from its recorded statistics; nullopt when neither
// (or when what was recorded is no box).
std::optional<openvdb::CoordBBox> activeBox(const io::detail::VdbContents& contents,
                                            const std::string& name) {
  if (const auto grid = io::detail::findGrid(contents, name)) return grid->evalActiveVoxelBoundingBox();
  const auto lo = recorded<openvdb::Vec3i>(contents, name, openvdb::GridBase::META_FILE_BBOX_MIN);
  const auto hi = recorded<openvdb::Vec3i>(contents, name, openvdb::GridBase::META_FILE_BBOX_MAX);
  if (!lo || !hi || (*lo)[0] > (*hi)[0] || (*lo)[1] > (*hi)[1] || (*lo)[2] > (*hi)[2]) return std::nullopt;
  return openvdb::CoordBBox(openvdb::Coord(*lo), openvdb::Coord(*hi));
}

std::uint64_t activeVoxelCount(const io::detail::VdbContents& contents, const std::string& name) {
  if (const auto grid = io::detail::findGrid(contents, name)) return grid->activeVoxelCount();
  return std::uint64_t(
      recorded<openvdb::Int64>(contents, name, openvdb::GridBase::META_FILE_VOXEL_COUNT).value_or(0));
}

// The grids readVdb makes dense (every grid, checked, when all are asked for). Those it does not
// still give the box (density and colour): a writer that recorded no box for one has it read after all.
io::detail::VdbContents gridsFor(const std::string& path, const VdbReadOptions& options) {
  if (options.density && options.color && options.particleId) return io::detail::readVdbGrids(path);
  std::vector<std::string> names;
  for (const auto& [wanted, name] :
       {std::pair{options.density, "density"}, std::pair{options.color, "color"},
        std::pair{options.particleId, "particle_id"}, std::pair{options.particleId, "phase"}})
    if (wanted) names.emplace_back(name);
  io::detail::VdbContents contents = io::detail::readVdbGrids(path, names);
  const std::size_t wanted = names.size();
  for (const char* name : {"density", "color"})
    if (unreadGrid(contents, name) && !activeBox(contents, name)) names.emplace_back(name);
  if (names.size() == wanted) return contents;
  contents = {};  // its trees are read again
  return io::detail::readVdbGrids(path, names);
}

// Ids a phase table may reach whatever the box: a 2048^3 solid of 32-voxel particles.
constexpr std::uint64_t kMostParticleIds = std::uint64_t(1) << 28;

// Each particle's phase (phase grid value - 1) from the voxels the two grids share.
std::vector<std::uint8_t> particlePhasesOf(const openvdb::Int32Grid& ids, const openvdb::Int32Grid& phase,
                                           const std::string& path, std::uint64_t voxels) {
  std::vector<std::uint8_t> out;
  const auto idAt = ids.getConstAccessor();
  for (auto it = phase.cbeginValueOn(); it; ++it) {
    const std::int32_t id = idAt.getValue(it.getCoord()), value = *it;
    if (id <= 0) continue;
    // A brick's file holds the whole volume's ids, more than its own voxels; beyond both, damage.
    if (std::uint64_t(id) > std::max(voxels, kMostParticleIds))
      throw InputError("cannot read " + path + ": damaged (a particle id beyond its voxels)");
    if (value < 1 || value > 255)
      throw InputError("cannot read " + path + ": its phase grid holds " + std::to_string(value) +
                       " on a particle (phases are 1 to 255)");
    if (std::size_t(id) > out.size()) out.resize(std::size_t(id), 0);
    out[std::size_t(id) - 1] = std::uint8_t(value - 1);
  }
  return out;
}

// Copies a grid into `out` over the box and lets its tree go.
template <typename GridT, typename Value>
void takeDense(typename GridT::Ptr& grid, const openvdb::CoordBBox& box, std::vector<Value>& out) {
  if (grid) denseFrom(*grid, box, out);
  grid.reset();
}

}  // namespace

SolidVolume readVdb(const std::string& path, const VdbReadOptions& options) {
  io::detail::VdbContents contents = gridsFor(path, options);
  openvdb::CoordBBox box;
  for (const char* name : {"density", "color"})
    box.expand(activeBox(contents, name).value_or(openvdb::CoordBBox()));
  if (box.empty()) throw InputError("cannot read " + path + ": no density or color grid with active voxels");
  SolidVolume volume;
  volume.activeVoxels = std::max(activeVoxelCount(contents, "density"), activeVoxelCount(contents, "color"));
  auto density = typedGrid<openvdb::FloatGrid>(contents, path, "density", "float");
  auto color = typedGrid<openvdb::Vec3SGrid>(contents, path, "color", "vec3s");
  auto ids = typedGrid<openvdb::Int32Grid>(contents, path, "particle_id", "int32");
  if (const auto phase = typedGrid<openvdb::Int32Grid>(contents, path, "phase", "int32"); phase && ids)
    volume.particlePhase = particlePhasesOf(*ids, *phase, path, std::uint64_t(box.volume()));
  contents.grids.clear();
  // Recorded bounds can be edited apart from the values: ids outside them would be dropped unseen.
  const bool recordedBox = unreadGrid(contents, "density") || unreadGrid(contents, "color");
  if (ids && recordedBox && !box.isInside(ids->evalActiveVoxelBoundingBox()))
    throw InputError("cannot read " + path +
                     ": damaged (its particle ids lie outside the bounds of its density and color grids)");
  if (!options.density) density.reset();
  if (!options.color) color.reset();
  checkBox(path, box,
           (density ? sizeof(float) : 0) + (color ? sizeof(Rgb) : 0) + (ids ? sizeof(std::int32_t) : 0));
  volume.dims = {box.dim().x(), box.dim().y(), box.dim().z()};
  takeDense<openvdb::FloatGrid>(density, box, volume.density);
  takeDense<openvdb::Vec3SGrid>(color, box, volume.color);
  takeDense<openvdb::Int32Grid>(ids, box, volume.particleId);
  for (auto it = contents.metadata->beginMeta(); it != contents.metadata->endMeta(); ++it)
    volume.metadata[it->first] = it->second->str();
  checkValues(path, volume);
  return volume;
}

}  // namespace solidtex
