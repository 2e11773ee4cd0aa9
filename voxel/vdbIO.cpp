#include "voxel/vdbIO.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <system_error>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "common/Error.h"
#include "voxel/writeVdbGrids.h"

namespace solidtex {
namespace {

static_assert(sizeof(Rgb) == sizeof(openvdb::Vec3s), "Rgb must be layout-compatible with Vec3s");

openvdb::CoordBBox boxOf(const Dims& dims) {
  return openvdb::CoordBBox(openvdb::Coord(0, 0, 0), openvdb::Coord(dims.x - 1, dims.y - 1, dims.z - 1));
}

/// Dense data in our x-fastest layout wrapped for OpenVDB without a copy.
template <typename VdbValue, typename Value>
openvdb::tools::Dense<VdbValue, openvdb::tools::LayoutXYZ> wrap(const Dims& dims,
                                                                const std::vector<Value>& data) {
  static_assert(sizeof(VdbValue) == sizeof(Value));
  return {boxOf(dims), reinterpret_cast<VdbValue*>(const_cast<Value*>(data.data()))};
}

template <typename GridT, typename Value>
typename GridT::Ptr sparseFrom(const Dims& dims, const std::vector<Value>& data,
                               const typename GridT::ValueType& tolerance, const std::string& name,
                               const openvdb::math::Transform::Ptr& xform) {
  auto grid = GridT::create(typename GridT::ValueType(openvdb::zeroVal<typename GridT::ValueType>()));
  openvdb::tools::copyFromDense(wrap<typename GridT::ValueType>(dims, data), *grid, tolerance);
  grid->setName(name);
  grid->setTransform(xform);
  return grid;
}

// density: the volume's own, or 1 on the particles (the active voxels of `ids`), or 1 everywhere.
openvdb::FloatGrid::Ptr densityGrid(const SolidVolume& volume, const openvdb::Int32Grid::Ptr& ids,
                                    const openvdb::math::Transform::Ptr& xform) {
  openvdb::FloatGrid::Ptr grid;
  if (!volume.density.empty()) {
    // Without colour the density is the content (a solid from a density volume): every voxel stays
    // active, zeros included, so the file keeps its box.
    const float tolerance = volume.color.empty() ? -1.f : 0.f;
    grid = sparseFrom<openvdb::FloatGrid>(volume.dims, volume.density, tolerance, "density", xform);
  } else if (ids) {
    grid = openvdb::FloatGrid::create(
        std::make_shared<openvdb::FloatTree>(ids->tree(), 0.f, 1.f, openvdb::TopologyCopy()));
  } else {
    grid = openvdb::FloatGrid::create(0.f);
    grid->denseFill(boxOf(volume.dims), 1.f, true);
  }
  grid->setName("density");
  grid->setTransform(xform);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  return grid;
}

template <typename T>
void release(std::vector<T>& data) {
  std::vector<T>().swap(data);
}

// Each dense array is released as soon as its grid is built, so the volume is never held twice.
openvdb::GridPtrVec gridsOf(SolidVolume& volume, double voxelSize) {
  auto xform = openvdb::math::Transform::createLinearTransform(voxelSize);
  // A region of a larger volume keeps its index space from 0 and is placed by its transform.
  xform->postTranslate(openvdb::Vec3d(volume.origin.x, volume.origin.y, volume.origin.z) * voxelSize);
  openvdb::Int32Grid::Ptr ids;
  if (!volume.particleId.empty())
    ids = sparseFrom<openvdb::Int32Grid>(volume.dims, volume.particleId, 0, "particle_id", xform);
  release(volume.particleId);
  openvdb::GridPtrVec grids;
  grids.push_back(densityGrid(volume, ids, xform));
  release(volume.density);
  if (!volume.color.empty()) {
    // A negative tolerance keeps every voxel active: colour must cover the whole box, black included.
    auto color =
        sparseFrom<openvdb::Vec3SGrid>(volume.dims, volume.color, openvdb::Vec3s(-1.f), "color", xform);
    release(volume.color);
    color->setVectorType(openvdb::VEC_INVARIANT);
    grids.push_back(color);
    auto cd = color->copyGrid();  // shares the tree: Houdini's name for the same data
    cd->setName("Cd");
    grids.push_back(cd);
  }
  if (ids) grids.push_back(ids);
  if (!volume.sourcePosition.empty()) {
    std::vector<Rgb> positions(volume.sourcePosition.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
      positions[i] = {volume.sourcePosition[i][0], volume.sourcePosition[i][1], 0.f};
    release(volume.sourcePosition);
    grids.push_back(sparseFrom<openvdb::Vec3SGrid>(volume.dims, positions, openvdb::Vec3s(-1.f),
                                                   "source_position", xform));
  }
  if (!volume.sourceVoxel.empty()) {
    grids.push_back(sparseFrom<openvdb::Vec3SGrid>(volume.dims, volume.sourceVoxel, openvdb::Vec3s(-1.f),
                                                   "source", xform));
    release(volume.sourceVoxel);
  }
  return grids;
}

// OpenVDB stamps each file with a random UUID: magic (8 bytes), format and library versions (12),
// grid-offsets flag (1), then 36 ASCII characters.
constexpr std::streamoff kUuidOffset = 21;
constexpr std::size_t kUuidLength = 36;

/// Replaces the random UUID by one hashed (FNV-1a, two seeds) from the rest of the file, so the
/// same volume gives the same bytes.
void stampContentUuid(const std::filesystem::path& file) {
  std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
  if (!io.is_open()) throw std::runtime_error("cannot reopen it to stamp its UUID");
  std::string uuid(kUuidLength, '\0');
  io.seekg(kUuidOffset);
  io.read(uuid.data(), std::streamsize(kUuidLength));
  if (!io || uuid[8] != '-' || uuid[13] != '-' || uuid[18] != '-' || uuid[23] != '-')
    throw std::logic_error("writeVdb: no UUID where OpenVDB's header keeps it");
  std::uint64_t hash[2] = {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull};
  io.seekg(0);
  std::vector<char> chunk(1 << 20);
  std::streamoff position = 0;
  while (io.read(chunk.data(), std::streamsize(chunk.size())) || io.gcount() > 0) {
    for (std::streamsize i = 0; i < io.gcount(); ++i, ++position) {
      if (position >= kUuidOffset && position < kUuidOffset + std::streamoff(kUuidLength)) continue;
      for (auto& h : hash) h = (h ^ std::uint8_t(chunk[std::size_t(i)])) * 0x100000001b3ull;
    }
  }
  io.clear();
  char text[kUuidLength + 1];
  std::snprintf(text, sizeof text, "%08x-%04x-%04x-%04x-%012llx", unsigned(hash[0] >> 32),
                unsigned(hash[0] >> 16) & 0xffffu, unsigned(hash[0]) & 0xffffu, unsigned(hash[1] >> 48),
                (unsigned long long)(hash[1] & 0xffffffffffffull));
  io.seekp(kUuidOffset);
  io.write(text, std::streamsize(kUuidLength));
  if (!io.flush()) throw std::runtime_error("writeVdb: cannot stamp the UUID");
}

}  // namespace

void writeVdbGrids(const std::string& path, const openvdb::GridPtrVec& grids, const openvdb::MetaMap& meta) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path temp = target.parent_path() / ("." + target.filename().string() + ".partial");
  try {
    openvdb::io::File file(temp.string());
    file.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
    file.write(grids, meta);
    file.close();
    stampContentUuid(temp);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    if (dynamic_cast<const std::logic_error*>(&e) || dynamic_cast<const std::bad_alloc*>(&e)) throw;
    throw InputError("cannot write " + path + ": " + e.what());
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw InputError("cannot write " + path + ": " + ec.message());
  }
}

void writeVdb(const std::string& path, SolidVolume volume, double voxelSize) {
  openvdb::initialize();
  if ((!volume.color.empty() || volume.density.empty()) && volume.color.size() != volume.dims.count())
    throw std::logic_error("writeVdb: colour grid does not match the volume's dimensions");
  openvdb::MetaMap meta;
  for (const auto& [key, value] : volume.metadata) meta.insertMeta(key, openvdb::StringMetadata(value));
  writeVdbGrids(path, gridsOf(volume, voxelSize), meta);
}

namespace {

template <typename GridT, typename Value>
void denseFrom(const openvdb::GridBase::Ptr& base, const openvdb::CoordBBox& box, std::vector<Value>& out) {
  auto grid = openvdb::gridPtrCast<GridT>(base);
  if (!grid) return;
  out.assign(box.volume(), Value{});
  openvdb::tools::Dense<typename GridT::ValueType, openvdb::tools::LayoutXYZ> dense(
      box, reinterpret_cast<typename GridT::ValueType*>(out.data()));
  openvdb::tools::copyToDense(*grid, dense);
}

}  // namespace

SolidVolume readVdb(const std::string& path) {
  openvdb::initialize();
  if (!std::filesystem::exists(path)) throw InputError("cannot read " + path + ": no such file");
  openvdb::io::File file(path);
  openvdb::GridPtrVecPtr grids;
  openvdb::MetaMap::Ptr meta;
  try {
    file.open();
    grids = file.getGrids();
    meta = file.getMetadata();
    file.close();
  } catch (const openvdb::Exception& e) {
    throw InputError("cannot read " + path + ": " + e.what());
  }
  SolidVolume volume;
  openvdb::CoordBBox box;
  for (const auto& grid : *grids)
    if (grid->getName() == "density" || grid->getName() == "color")
      box.expand(grid->evalActiveVoxelBoundingBox());
  if (box.empty()) throw InputError("cannot read " + path + ": no density or color grid");
  volume.dims = {box.dim().x(), box.dim().y(), box.dim().z()};
  for (const auto& grid : *grids) {
    const auto& name = grid->getName();
    if (name == "density")
      denseFrom<openvdb::FloatGrid>(grid, box, volume.density);
    else if (name == "color")
      denseFrom<openvdb::Vec3SGrid>(grid, box, volume.color);
    else if (name == "particle_id")
      denseFrom<openvdb::Int32Grid>(grid, box, volume.particleId);
  }
  for (auto it = meta->beginMeta(); it != meta->endMeta(); ++it)
    volume.metadata[it->first] = it->second->str();
  return volume;
}

}  // namespace solidtex
