#include "io/writeVti.h"

#include <cstdint>
#include <sstream>

#include "common/writeFileBytes.h"

namespace solidtex {

void writeVti(const std::string& path, const Dims& dims, const Voxel& origin, double spacing,
              const std::vector<VtiArray>& arrays) {
  std::vector<std::uint64_t> sizes;
  std::ostringstream xml;
  xml.precision(17);
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "  <ImageData WholeExtent=\"0 " << dims.x << " 0 " << dims.y << " 0 " << dims.z << "\" Origin=\""
      << (origin.x - 0.5) * spacing << ' ' << (origin.y - 0.5) * spacing << ' ' << (origin.z - 0.5) * spacing
      << "\" Spacing=\"" << spacing << ' ' << spacing << ' ' << spacing << "\">\n"
      << "    <Piece Extent=\"0 " << dims.x << " 0 " << dims.y << " 0 " << dims.z << "\">\n"
      << "      <CellData>\n";
  std::uint64_t offset = 0;
  for (const VtiArray& array : arrays) {
    sizes.push_back(std::uint64_t(dims.count()) * array.components * array.componentBytes);
    xml << "        <DataArray type=\"" << array.type << "\" Name=\"" << array.name
        << "\" NumberOfComponents=\"" << array.components << "\" format=\"appended\" offset=\"" << offset
        << "\"/>\n";
    offset += sizeof(std::uint64_t) + sizes.back();
  }
  xml << "      </CellData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";
  const std::string head = xml.str(), tail = "\n  </AppendedData>\n</VTKFile>\n";
  std::vector<ByteSpan> parts{{head.data(), head.size()}};
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    parts.push_back({&sizes[a], sizeof(std::uint64_t)});
    parts.push_back({arrays[a].data, sizes[a]});
  }
  parts.push_back({tail.data(), tail.size()});
  writeFileBytes(path, parts);
}

}  // namespace solidtex
