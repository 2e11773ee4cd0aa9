#include "io/detail/vdbGrids.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <openvdb/io/Archive.h>
#include <openvdb/io/File.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/io/io.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/parallel_for.h>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "io/checkVdbLayout.h"
#include "io/detail/CapturedStderr.h"
#include "io/detail/valuesChecksum.h"

namespace solidtex::io::detail {
namespace {

// OpenVDB stamps each file with a random UUID: magic (8 bytes), format and library versions (12),
// grid-offsets flag (1), then 36 ASCII characters.
constexpr std::streamoff kUuidOffset = 21;
constexpr std::size_t kUuidLength = 36;

/// Replaces the random UUID by one hashed (FNV-1a, two seeds) from the rest of the file, so the
/// same volume gives the same bytes. It is a version-8 UUID (RFC 9562's own format), which OpenVDB's
/// random version-4 ones never are: a file re-saved by another tool is told from solidtex's own.
void stampContentUuid(const std::filesystem::path& file) {
  std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
  if (!io.is_open())
    throw InputError("cannot write " + file.string() + ": cannot reopen it to stamp its UUID");
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
                unsigned(hash[0] >> 16) & 0xffffu, 0x8000u | (unsigned(hash[0]) & 0x0fffu),
                0x8000u | (unsigned(hash[1] >> 48) & 0x3fffu),
                (unsigned long long)(hash[1] & 0xffffffffffffull));
  io.seekp(kUuidOffset);
  io.write(text, std::streamsize(kUuidLength));
  if (!io.flush()) throw InputError("cannot write " + file.string() + ": cannot stamp its UUID");
}

// What reading a file may take: a damaged block inside a grid can still ask OpenVDB for memory
// without end. Real files expand far less than a thousandfold, their trees being sparse themselves.
std::uint64_t readingAllowance(const std::string& path) {
  std::error_code ec;
  const double bytes = std::max(1024.0 * double(std::filesystem::file_size(path, ec)), double(1u << 30));
  return std::uint64_t(std::min(bytes, double(availableMemoryBytes())));
}

// "density grid", or "Cd and color grids" for grids that share one tree.
std::string gridsSharing(const openvdb::GridBase& grid, const openvdb::GridPtrVec& grids) {
  std::string names;
  int count = 0;
  for (const auto& other : grids)
    if (&other->constBaseTree() == &grid.constBaseTree())
      names += (count++ == 0 ? "" : " and ") + other->getName();
  return names + (count > 1 ? " grids" : " grid");
}

bool stampedBySolidtex(const std::string& uuid) { return uuid.size() == kUuidLength && uuid[14] == '8'; }

// Every grid of a file solidtex wrote that carries its checksum must still have the values it was
// written with (a tree shared by several grids is checked once). A file another tool re-saved keeps
// the grids' metadata, checksums included, but has its own UUID: its values may have been edited.
void checkValues(const std::string& path, const openvdb::GridPtrVec& grids) {
  std::map<const openvdb::TreeBase*, std::optional<std::uint64_t>> checksums;
  for (const auto& grid : grids) {
    const auto written = grid->getMetadata<openvdb::StringMetadata>(kValuesChecksumName);
    if (!written) continue;
    const auto known = checksums.try_emplace(&grid->constBaseTree());
    if (known.second) known.first->second = valuesChecksum(*grid);
    if (!known.first->second || checksumText(*known.first->second) != written->value())
      throw InputError("cannot read " + path + ": damaged (the values of its " + gridsSharing(*grid, grids) +
                       " do not match the checksum written with them)");
  }
}

}  // namespace

// OpenVDB's messages about a damaged file can quote whatever bytes it found (a "grid type" of 800
// spaces, or of a gigabyte): keep printable characters, one space between words, and a short line.
std::string readableReason(const std::string& what) {
  constexpr std::size_t kLongest = 160;
  std::string out;
  for (const char c : what) {
    if (out.size() >= kLongest) {
      out += "...";
      break;
    }
    const bool printable = c >= 0x21 && c <= 0x7e;
    if (printable)
      out += c;
    else if (!out.empty() && out.back() != ' ')
      out += ' ';
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.empty() ? "damaged file" : out;
}

// OpenVDB's own file writer does not check the stream it writes, and wants every grid at once:
// this one writes the same bytes (a seekable archive; each grid with its checksum) group by group,
// to a stream whose every failure is seen.
class CheckedArchive : public openvdb::io::Archive {
public:
  void writeTo(std::ostream& out, const std::vector<GridGroupMaker>& groups,
               const openvdb::MetaMap& meta) const {
    auto streamMetadata = std::make_shared<openvdb::io::StreamMetadata>();
    openvdb::io::setStreamMetadataPtr(out, streamMetadata, /*transfer=*/false);
    openvdb::io::setDataCompression(out, compression());
    openvdb::io::setWriteGridStatsMetadata(out, isGridStatsMetadataEnabled());
    writeHeader(out, /*seekable=*/true);
    meta.writeMeta(out);
    // The grid count comes before the grids, which are not made yet: written once they are.
    const std::streampos countAt = out.tellp();
    std::int32_t count = 0;
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    std::set<std::string> names;
    for (const GridGroupMaker& makeGroup : groups) {
      std::map<const openvdb::TreeBase*, openvdb::io::GridDescriptor> writtenTrees;
      std::map<const openvdb::TreeBase*, std::optional<std::uint64_t>> checksums;
      const GridGroup group = makeGroup();
      for (const openvdb::GridBase::Ptr& grid : group.grids) {
        if (grid->getName().empty() || !names.insert(grid->getName()).second)
          throw std::logic_error("writeVdbGrids: grid names must be unique and non-empty");
        const auto painter = group.painters.find(&grid->baseTree());
        if (painter != group.painters.end() && !writtenTrees.count(&grid->baseTree())) {
          checksums[&grid->baseTree()] = writePainted(out, grid, painter->second, writtenTrees);
        } else {
          const auto known = checksums.try_emplace(&grid->baseTree());
          if (known.second) known.first->second = valuesChecksum(*grid);
          writeOne(out, withChecksum(grid, known.first->second), writtenTrees);
        }
        ++count;
        // Some compression settings (the active mask's) are per grid.
        openvdb::io::setDataCompression(out, compression());
      }
    }
    out.seekp(countAt);
    out.write(reinterpret_cast<const char*>(&count), sizeof count);
    out.seekp(0, std::ios::end);
  }

private:
  // A shallow copy (same tree) carrying the checksum, so the caller's grid is left as it was.
  static openvdb::GridBase::Ptr withChecksum(const openvdb::GridBase::Ptr& grid,
                                             const std::optional<std::uint64_t>& checksum) {
    if (!checksum) return grid;
    openvdb::GridBase::Ptr copy = grid->copyGrid();
    copy->insertMeta(kValuesChecksumName, openvdb::StringMetadata(checksumText(*checksum)));
    return copy;
  }

  // Archive::writeGrid's steps, with the values painted and written a batch of leaves at a time
  // and the checksum put in the metadata once they are all written.
  std::uint64_t writePainted(
      std::ostream& out, const openvdb::GridBase::Ptr& grid, const LeafPainter& paint,
      std::map<const openvdb::TreeBase*, openvdb::io::GridDescriptor>& writtenTrees) const {
    const auto typed = openvdb::GridBase::grid<openvdb::Vec3SGrid>(grid);
    if (!typed || grid->saveFloatAsHalf())
      throw std::logic_error("writeVdbGrids: only Vec3s grids saved as floats are painted");
    openvdb::io::GridDescriptor descriptor(grid->getName(), grid->type(), grid->saveFloatAsHalf());
    descriptor.writeHeader(out);
    const std::streampos offsets = out.tellp();
    descriptor.writeStreamPos(out);
    descriptor.setGridPos(out.tellp());
    setGridCompression(out, *grid);
    const std::string placeholder(16, '?');
    const openvdb::GridBase::Ptr copy = grid->copyGrid();
    copy->addStatsMetadata();  // from the topology: bounds and voxel count
    // The memory the grid takes once read: its leaves' values too, which this tree does not hold.
    const auto leafValueBytes = std::int64_t(typed->tree().leafCount() *
                                             openvdb::Vec3STree::LeafNodeType::SIZE * sizeof(openvdb::Vec3s));
    copy->insertMeta(openvdb::GridBase::META_FILE_MEM_BYTES,
                     openvdb::Int64Metadata(std::int64_t(grid->memUsage()) + leafValueBytes));
    copy->insertMeta(
        openvdb::GridBase::META_FILE_COMPRESSION,
        openvdb::StringMetadata(openvdb::io::compressionToString(openvdb::io::getDataCompression(out))));
    copy->insertMeta(kValuesChecksumName, openvdb::StringMetadata(placeholder));
    std::ostringstream meta;
    copy->writeMeta(meta);
    const std::string metaBytes = meta.str();
    if (metaBytes.find(placeholder) == std::string::npos)
      throw std::logic_error("writeVdbGrids: no checksum placeholder in the grid's metadata");
    const std::streampos checksumAt = out.tellp() + std::streamoff(metaBytes.find(placeholder));
    out.write(metaBytes.data(), std::streamsize(metaBytes.size()));
    grid->writeTransform(out);
    grid->writeTopology(out);
    descriptor.setBlockPos(out.tellp());
    const std::uint64_t checksum = writePaintedLeaves(out, typed->tree(), paint);
    descriptor.setEndPos(out.tellp());
    out.seekp(offsets);
    descriptor.writeStreamPos(out);
    out.seekp(checksumAt);
    out.write(checksumText(checksum).data(), std::streamsize(placeholder.size()));
    descriptor.seekToEnd(out);
    writtenTrees[&grid->baseTree()] = descriptor;
    return checksum;
  }

  // The leaves in tree order (RootNode::writeBuffers'), each batch painted in parallel.
  static std::uint64_t writePaintedLeaves(std::ostream& out, const openvdb::Vec3STree& tree,
                                          const LeafPainter& paint) {
    using Leaf = openvdb::Vec3STree::LeafNodeType;
    constexpr std::size_t kBatch = 4096;  // 24 MiB of values
    const openvdb::tree::LeafManager<const openvdb::Vec3STree> leaves(tree);
    std::vector<std::unique_ptr<Leaf>> batch;
    for (std::size_t i = 0; i < std::min(kBatch, leaves.leafCount()); ++i)
      batch.push_back(std::make_unique<Leaf>());
    std::vector<std::uint64_t> leafChecksums(leaves.leafCount());
    for (std::size_t first = 0; first < leaves.leafCount(); first += kBatch) {
      const std::size_t count = std::min(kBatch, leaves.leafCount() - first);
      tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) {
        const Leaf& source = leaves.leaf(first + i);
        Leaf& leaf = *batch[i];
        leaf.setOrigin(source.origin());
        leaf.setValueMask(source.getValueMask());
        paint(source.origin(), leaf.buffer().data());
        leafChecksums[first + i] = leafChecksum(leaf);
      });
      for (std::size_t i = 0; i < count; ++i) batch[i]->writeBuffers(out, /*toHalf=*/false);
    }
    return valuesChecksum(tree, leafChecksums);
  }

  void writeOne(std::ostream& out, const openvdb::GridBase::Ptr& grid,
                std::map<const openvdb::TreeBase*, openvdb::io::GridDescriptor>& writtenTrees) const {
    openvdb::io::GridDescriptor descriptor(grid->getName(), grid->type(), grid->saveFloatAsHalf());
    const openvdb::TreeBase* tree = &grid->baseTree();
    const auto parent = writtenTrees.find(tree);
    if (isInstancingEnabled() && parent != writtenTrees.end() &&
        parent->second.saveFloatAsHalf() == descriptor.saveFloatAsHalf()) {
      descriptor.setInstanceParentName(parent->second.uniqueName());
      writeGridInstance(descriptor, grid, out, /*seekable=*/true);
    } else {
      writeGrid(descriptor, grid, out, /*seekable=*/true);
      writtenTrees[tree] = descriptor;
    }
  }
};

void writeVdbGrids(const std::string& path, const std::vector<GridGroupMaker>& groups,
                   const openvdb::MetaMap& meta) {
  try {
    std::ofstream out(path, std::ios::out | std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot write " + path + ": " + std::strerror(errno));
    CheckedArchive archive;
    archive.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
    archive.writeTo(out, groups, meta);
    out.close();
    if (!out) throw InputError("cannot write " + path + ": " + std::strerror(errno ? errno : ENOSPC));
    stampContentUuid(path);
  } catch (const openvdb::Exception& e) {
    throw InputError("cannot write " + path + ": " + e.what());
  } catch (const std::ios_base::failure& e) {
    throw InputError("cannot write " + path + ": " + e.what());
  }
}

void writeVdbGrids(const std::string& path, const openvdb::GridPtrVec& grids, const openvdb::MetaMap& meta) {
  writeVdbGrids(path, {[&grids] { return grids; }}, meta);
}

VdbContents readVdbGrids(const std::string& path, const std::vector<std::string>& only) {
  openvdb::initialize();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("cannot read " + path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError("cannot read " + path + ": it is a folder");
  checkVdbLayout(path);
  VdbContents contents;
  bool stamped = false;
  // OpenVDB prints warnings on damaged files ("multi-buffer trees are no longer supported"): the
  // command's error, if any, is the one line.
  detail::CapturedStderr libraryOutput;
  try {
    const MemoryCap cap(readingAllowance(path));
    openvdb::io::File file(path);
    file.open(/*delayLoad=*/false);
    if (only.empty()) contents.grids = *file.getGrids();
    for (const std::string& name : only)
      if (file.hasGrid(name)) contents.grids.push_back(file.readGrid(name));
    const openvdb::GridPtrVecPtr described = only.empty() ? nullptr : file.readAllGridMetadata();
    if (described)
      for (const auto& grid : *described)
        if (std::find(only.begin(), only.end(), grid->getName()) == only.end())
          contents.unread.push_back(grid);
    contents.metadata = file.getMetadata();
    stamped = stampedBySolidtex(file.getUniqueTag());
    file.close();
  } catch (const std::bad_alloc&) {
    throw InputError("cannot read " + path + ": damaged (a size in it asks for more memory than there is)");
  } catch (const std::exception& e) {
    throw InputError("cannot read " + path + ": not a readable OpenVDB file (" + readableReason(e.what()) +
                     ")");
  }
  for (const auto& grid : contents.grids)
    if (!grid) throw InputError("cannot read " + path + ": damaged (a grid could not be read)");
  if (stamped) checkValues(path, contents.grids);
  return contents;
}

openvdb::GridBase::Ptr findGrid(const VdbContents& contents, const std::string& name) {
  for (const auto& grid : contents.grids)
    if (grid->getName() == name) return grid;
  return nullptr;
}

}  // namespace solidtex::io::detail
