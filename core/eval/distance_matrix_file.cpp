// Writing and strictly reading the distance matrix file of argtool eval --matrix.
#include "eval/distance_matrix_file.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/errors.hpp"

namespace arg {

namespace {

void append_exact(std::string& out, double x) {
  if (std::isinf(x)) {
    out += x > 0 ? "inf" : "-inf";
    return;
  }
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  out += buf;
}

}  // namespace

std::string format_distance_matrix(const DistanceMatrix& m) {
  std::string out;
  out.reserve(m.n * m.n * 10);
  for (std::size_t i = 0; i < m.n; ++i) {
    for (std::size_t j = 0; j < m.n; ++j) {
      if (j) out += ' ';
      const bool missing = !m.valid.empty() && (!m.valid[i] || !m.valid[j]);
      append_exact(out, missing ? HUGE_VAL : m.distance[i * m.n + j]);
    }
    out += '\n';
  }
  return out;
}

DistanceMatrix parse_distance_matrix(std::string_view text) {
  std::vector<std::vector<double>> rows;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    at = end + 1;
    const std::string where = "distance matrix: line " + std::to_string(rows.size() + 1);
    std::vector<double>& row = rows.emplace_back();
    std::size_t p = 0;
    while (p < line.size()) {
      std::size_t q = line.find(' ', p);
      if (q == std::string_view::npos) q = line.size();
      std::string field(line.substr(p, q - p));
      if (field.empty()) throw InputError(where + ": empty field");
      double x;
      if (field == "inf") {
        x = HUGE_VAL;
      } else {
        auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), x);
        if (ec != std::errc() || ptr != field.data() + field.size() || !std::isfinite(x))
          throw InputError(where + ": \"" + field + "\" is not a finite number or inf");
      }
      row.push_back(x);
      p = q + 1;
    }
  }
  DistanceMatrix m;
  m.n = rows.size();
  m.distance.reserve(m.n * m.n);
  m.valid.assign(m.n, true);
  for (std::size_t i = 0; i < m.n; ++i) {
    if (rows[i].size() != m.n)
      throw InputError("distance matrix: line " + std::to_string(i + 1) + " has " +
                       std::to_string(rows[i].size()) + " numbers, expected " +
                       std::to_string(m.n));
    m.distance.insert(m.distance.end(), rows[i].begin(), rows[i].end());
    m.valid[i] = std::isfinite(rows[i][i]);
  }
  return m;
}

}  // namespace arg
