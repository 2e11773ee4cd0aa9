#include "mesh/writeParticleMeshes.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>

#include "common/Error.h"
#include "common/srgb.h"
#include "common/writeFileBytes.h"

namespace solidtex {
namespace {

static_assert(std::endian::native == std::endian::little, "PLY files are written as little-endian");

bool isObj(const std::string& path) { return std::filesystem::path(path).extension() == ".obj"; }

std::string mtlPathOf(const std::string& objPath) {
  return std::filesystem::path(objPath).replace_extension(".mtl").string();
}

template <typename T>
void append(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void appendNumber(std::string& text, double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 7).ptr;
  text.append(buffer, end);
}

std::uint8_t srgbByte(float linear) { return std::uint8_t(std::lround(255 * linearToSrgb(linear))); }

std::string particleName(int id) { return "particle_" + std::to_string(id); }

}  // namespace

void writePly(const std::string& path, std::span<const ParticleMesh> meshes) {
  std::size_t vertexCount = 0, faceCount = 0;
  for (const ParticleMesh& m : meshes) {
    vertexCount += m.surface.vertices.size();
    faceCount += m.surface.triangles.size();
  }
  if (vertexCount > std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw InputError("cannot write " + path + ": more vertices than a PLY's int indices reach");
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\n"
      "comment solidtex particle meshes: voxel (i,j,k) of the .vdb centred at (i,j,k)\n"
      "element vertex " +
      std::to_string(vertexCount) +
      "\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int particle_id\n"
      "element face " +
      std::to_string(faceCount) +
      "\nproperty list uchar int vertex_indices\nproperty int particle_id\nend_header\n";
  bytes.reserve(bytes.size() + vertexCount * 19 + faceCount * 17);
  for (const ParticleMesh& m : meshes)
    for (const Eigen::Vector3d& v : m.surface.vertices) {
      for (int a = 0; a < 3; ++a) append(bytes, float(v[a]));
      for (const float c : m.color) append(bytes, srgbByte(c));
      append(bytes, std::int32_t(m.id));
    }
  std::int32_t first = 0;
  for (const ParticleMesh& m : meshes) {
    for (const auto& t : m.surface.triangles) {
      append(bytes, std::uint8_t(3));
      for (const int corner : t) append(bytes, std::int32_t(first + corner));
      append(bytes, std::int32_t(m.id));
    }
    first += std::int32_t(m.surface.vertices.size());
  }
  writeFileBytes(path, bytes.data(), bytes.size());
}

void writeObj(const std::string& path, const std::string& mtlName, std::span<const ParticleMesh> meshes) {
  std::string text =
      "# solidtex particle meshes: voxel (i,j,k) of the .vdb centred at (i,j,k)\nmtllib " + mtlName + "\n";
  std::size_t first = 1;  // OBJ counts vertices from 1 across the file
  for (const ParticleMesh& m : meshes) {
    const std::string name = particleName(m.id);
    text += "o " + name + "\nusemtl " + name + "\n";
    for (const Eigen::Vector3d& v : m.surface.vertices) {
      text += 'v';
      for (int a = 0; a < 3; ++a) {
        text += ' ';
        appendNumber(text, v[a]);
      }
      text += '\n';
    }
    for (const auto& t : m.surface.triangles)
      text += "f " + std::to_string(first + std::size_t(t[0])) + ' ' +
              std::to_string(first + std::size_t(t[1])) + ' ' + std::to_string(first + std::size_t(t[2])) +
              '\n';
    first += m.surface.vertices.size();
  }
  writeFileBytes(path, text.data(), text.size());
}

void writeMtl(const std::string& path, std::span<const ParticleMesh> meshes) {
  std::string text = "# solidtex particle colours, linear RGB\n";
  for (const ParticleMesh& m : meshes) {
    text += "newmtl " + particleName(m.id) + "\nKd";
    for (const float c : m.color) {
      text += ' ';
      appendNumber(text, c);
    }
    text += '\n';
  }
  writeFileBytes(path, text.data(), text.size());
}

void addParticleMeshes(OutputFiles& outputs, const std::string& option, const std::string& path) {
  outputs.addFile(option, path, {".ply", ".obj"});
  if (isObj(path)) outputs.addFile(option, mtlPathOf(path), {".mtl"});
}

std::vector<std::string> writeParticleMeshes(OutputFiles& outputs, const std::string& path,
                                             const std::vector<ParticleMesh>& meshes) {
  if (!isObj(path)) {
    outputs.write(path, [&](const std::string& file) { writePly(file, meshes); });
    return {path};
  }
  const std::string mtl = mtlPathOf(path);
  outputs.write(mtl, [&](const std::string& file) { writeMtl(file, meshes); });
  const std::string mtlName = std::filesystem::path(mtl).filename().string();
  outputs.write(path, [&](const std::string& file) { writeObj(file, mtlName, meshes); });
  return {path, mtl};
}

}  // namespace solidtex
