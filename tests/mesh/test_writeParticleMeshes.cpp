#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "common/Error.h"
#include "mesh/writeParticleMeshes.h"
#include "tests/mesh/cube.h"
#include "tests/scratchPath.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;
using V = Eigen::Vector3d;

fs::path scratch(const std::string& name) { return test::scratchPath("mesh_test", name); }

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<ParticleMesh> twoBoxes() {
  return {{3, {1.0f, 0.0f, 0.2f}, test::boxMesh(V(0, 0, 0), V(1, 1, 1))},
          {7, {0.0f, 0.5f, 1.0f}, test::boxMesh(V(2, 0, 0), V(3, 2, 1))}};
}

template <typename T>
T read(const std::string& bytes, std::size_t& at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

TEST(WritePly, BinaryVerticesColoursAndIdsReadBack) {
  const fs::path path = scratch("boxes.ply");
  const auto meshes = twoBoxes();
  writePly(path.string(), meshes);
  const std::string bytes = bytesOf(path);
  const std::size_t end = bytes.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  const std::string header = bytes.substr(0, end);
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex 16\n"), std::string::npos);
  EXPECT_NE(header.find("element face 24\n"), std::string::npos);
  std::size_t at = end + 11;
  for (const ParticleMesh& m : meshes)
    for (const Eigen::Vector3d& v : m.surface.vertices) {
      for (int a = 0; a < 3; ++a) EXPECT_EQ(read<float>(bytes, at), float(v[a]));
      const std::uint8_t red = read<std::uint8_t>(bytes, at), green = read<std::uint8_t>(bytes, at),
                         blue = read<std::uint8_t>(bytes, at);
      EXPECT_EQ(red, m.id == 3 ? 255 : 0);
      EXPECT_EQ(green, m.id == 3 ? 0 : 188);  // sRGB of linear 0.5
      EXPECT_EQ(blue, m.id == 3 ? 124 : 255);
      EXPECT_EQ(read<std::int32_t>(bytes, at), m.id);
    }
  int first = 0;
  for (const ParticleMesh& m : meshes) {
    for (const auto& t : m.surface.triangles) {
      EXPECT_EQ(read<std::uint8_t>(bytes, at), 3);
      for (const int corner : t) EXPECT_EQ(read<std::int32_t>(bytes, at), first + corner);
      EXPECT_EQ(read<std::int32_t>(bytes, at), m.id);
    }
    first += int(m.surface.vertices.size());
  }
  EXPECT_EQ(at, bytes.size());
}

TEST(WriteObj, ObjectsMaterialsAndGlobalIndices) {
  OutputFiles outputs;
  const fs::path path = scratch("boxes.obj");
  addParticleMeshes(outputs, "--meshes", path.string());
  const auto written = writeParticleMeshes(outputs, path.string(), twoBoxes());
  outputs.commit();
  EXPECT_EQ(written, (std::vector<std::string>{path.string(), scratch("boxes.mtl").string()}));

  std::istringstream obj(bytesOf(path));
  std::string line;
  int vertices = 0, faces = 0, largestIndex = 0;
  std::vector<std::string> objects;
  while (std::getline(obj, line)) {
    if (line.rfind("o ", 0) == 0) objects.push_back(line.substr(2));
    if (line.rfind("usemtl ", 0) == 0) {
      EXPECT_EQ(line.substr(7), objects.back());
    }
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      std::istringstream f(line.substr(2));
      for (int i; f >> i;) largestIndex = std::max(largestIndex, i);
    }
  }
  EXPECT_NE(bytesOf(path).find("mtllib boxes.mtl\n"), std::string::npos);
  EXPECT_EQ(objects, (std::vector<std::string>{"particle_3", "particle_7"}));
  EXPECT_EQ(vertices, 16);
  EXPECT_EQ(faces, 24);
  EXPECT_EQ(largestIndex, 16);  // counted from 1 across the file
  EXPECT_EQ(bytesOf(scratch("boxes.mtl")),
            "# solidtex particle colours, linear RGB\nnewmtl particle_3\nKd 1 0 0.2\n"
            "newmtl particle_7\nKd 0 0.5 1\n");
}

TEST(WriteParticleMeshes, TakesPlyOrObjAndRefusesAnythingElse) {
  const fs::path ply = scratch("staged.ply");
  fs::remove(ply);
  {
    OutputFiles outputs;
    addParticleMeshes(outputs, "--meshes", ply.string());
    EXPECT_EQ(writeParticleMeshes(outputs, ply.string(), twoBoxes()), std::vector<std::string>{ply.string()});
    outputs.commit();
  }
  EXPECT_NE(bytesOf(ply).find("element vertex 16\n"), std::string::npos);
  OutputFiles outputs;
  EXPECT_THROW(addParticleMeshes(outputs, "--meshes", scratch("meshes").string()), InputError);
  EXPECT_THROW(addParticleMeshes(outputs, "--meshes", scratch("meshes.stl").string()), InputError);
}

}  // namespace
}  // namespace solidtex
