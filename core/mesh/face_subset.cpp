// Copying the kept faces and their colours.
#include "mesh/face_subset.hpp"

#include <algorithm>

namespace arg {

Mesh face_subset(const Mesh& mesh, const std::vector<char>& keep) {
  Mesh out;
  out.V = mesh.V;
  const auto kept = Eigen::Index(std::count_if(keep.begin(), keep.end(), [](char k) { return k; }));
  out.F.resize(kept, 3);
  if (mesh.has_colour()) out.C.resize(kept, 3);
  Eigen::Index at = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (keep[std::size_t(f)]) {
      out.F.row(at) = mesh.F.row(f);
      if (mesh.has_colour()) out.C.row(at) = mesh.C.row(f);
      ++at;
    }
  return out;
}

}  // namespace arg
