// The counts a file declares reach the caller before the reader allocates for them.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "test_shapes.hpp"

using namespace arg;

namespace {

struct Declared {
  std::size_t vertices = 0, faces = 0;
  int calls = 0;
};

Declared declared_by(const std::string& bytes) {
  Declared d;
  ReadOptions read;
  read.declared_counts = [&](std::size_t vertices, std::size_t faces) {
    d.vertices = vertices, d.faces = faces;
    ++d.calls;
  };
  read_mesh(bytes, read);
  return d;
}

}  // namespace

TEST(DeclaredCounts, EachFormatDeclaresItsCountsOnce) {
  const Mesh torus = test::torus(2, 0.6, 40, 20);
  const std::size_t v = std::size_t(torus.V.rows()), f = std::size_t(torus.F.rows());
  for (const auto& [name, bytes] :
       std::vector<std::pair<std::string, std::string>>{{"PLY", write_ply_binary(torus)},
                                                        {"OFF", write_off(torus)},
                                                        {"OBJ", write_obj(torus)}}) {
    const Declared d = declared_by(bytes);
    EXPECT_EQ(d.calls, 1) << name;
    EXPECT_EQ(d.vertices, v) << name;
    EXPECT_EQ(d.faces, f) << name;
  }
  // A binary STL counts triangles only; its welded vertices are taken as half of them, which a
  // closed surface of genus one has exactly.
  const Declared stl = declared_by(write_stl_binary(torus));
  EXPECT_EQ(stl.calls, 1);
  EXPECT_EQ(stl.faces, f);
  EXPECT_EQ(stl.vertices, v);
}

TEST(DeclaredCounts, ARefusalEndsTheReadBeforeItsFirstVertex) {
  const Mesh torus = test::torus(2, 0.6, 200, 100);  // 20,000 vertices: the reader polls
  for (const std::string& bytes :
       {write_ply_binary(torus), write_off(torus), write_obj(torus), write_stl_binary(torus)}) {
    int polls = 0;
    ReadOptions read;
    read.stop = [&] {
      ++polls;
      return false;
    };
    read.declared_counts = [](std::size_t, std::size_t) { throw LimitError("refused"); };
    EXPECT_THROW(read_mesh(bytes, read), LimitError);
    EXPECT_EQ(polls, 0);
    read.declared_counts = nullptr;
    read_mesh(bytes, read);
    EXPECT_GT(polls, 0);
  }
}
