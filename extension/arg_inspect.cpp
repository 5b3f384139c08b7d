// Looking inside an ARG: arg_nodes (one row per node), arg_info (jsonb summary) and arg_svg
// (one level's Reeb graph as a picture).
#include <cstdlib>

#include "graph/comparable.hpp"
#include "graph/serialize.hpp"
#include "render/graph_svg.hpp"

#include "arg_bridge.hpp"

// funcapi.h reaches PostgreSQL's spinlock headers, which use `register` (not C++17).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wregister"
extern "C" {
#include "funcapi.h"
#include "utils/builtins.h"
#include "utils/fmgrprotos.h"
#include "utils/tuplestore.h"
}
#pragma GCC diagnostic pop

namespace {

// A row of arg_nodes: plain data, filled inside guarded() and emitted after it.
struct NodeRow {
  int32 level, node, parent;  // parent -1: none (level 0)
  float4 area, mu_min, mu_max, r, theta, phi, volume;
};

// The shortest decimal that reads back as the same float, as JSON.
std::string json_number(float x) {
  char buf[32];
  for (int digits = 6; digits <= 9; ++digits) {
    snprintf(buf, sizeof buf, "%.*g", digits, double(x));
    if (std::strtof(buf, nullptr) == x) break;
  }
  return buf;
}

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;  // the core's texts have none
    out += c;
  }
  return out + "\"";
}

std::string describe(const arg::ArgGraph& g, std::size_t bytes) {
  std::string per_level;
  for (int r = 0; r <= g.levels(); ++r)
    per_level += (r ? ", " : "") +
                 std::to_string(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)]);
  const arg::ArgSummary& s = g.summary;
  return "{\"levels\": " + std::to_string(g.levels()) +
         ", \"nodes\": " + std::to_string(g.nodes.size()) + ", \"nodes_per_level\": [" + per_level +
         "], \"edges\": " + std::to_string(g.adjacency.size() / 2) +
         ", \"genus_estimate\": " + std::to_string(s.genus) +
         ", \"components\": " + std::to_string(s.components) +
         ", \"triangles\": " + std::to_string(s.triangles) +
         ", \"vertices\": " + std::to_string(s.vertices) + ", \"area\": " + json_number(s.area) +
         ", \"volume\": " + json_number(s.volume) +
         ", \"has_colour\": " + (s.has_colour ? "true" : "false") +
         ", \"open\": " + ((s.flags & arg::kFlagOpen) ? "true" : "false") +
         ", \"wide_open\": " + ((s.flags & arg::kFlagWideOpen) ? "true" : "false") +
         ", \"proxy\": " + ((s.flags & arg::kFlagProxy) ? "true" : "false") +
         ", \"pooled_components\": " + std::to_string(s.pooled) +
         ", \"whole_shape\": " + (g.panorama.empty() ? "false" : "true") +
         ", \"options\": " + json_string(arg::format_build_options(g.options)) +
         ", \"builder_version\": " + json_string(arg::builder_version_text(g.builder_version)) +
         ", \"format_version\": " + std::to_string(g.format) +
         ", \"bytes\": " + std::to_string(bytes) + "}";
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_nodes);
PG_FUNCTION_INFO_V1(arg_info);
PG_FUNCTION_INFO_V1(arg_svg);

// arg_nodes(arg) RETURNS TABLE (level, node, parent, area, mu_min, mu_max, r, theta, phi, volume)
Datum arg_nodes(PG_FUNCTION_ARGS) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  NodeRow* rows = nullptr;
  std::size_t count = 0;
  argpg::Outcome out = argpg::guarded([&] {
    const arg::ArgGraph g = arg::deserialize_arg(argpg::view(value), /*check_digest=*/false);
    rows = static_cast<NodeRow*>(argpg::alloc_records(g.nodes.size(), sizeof(NodeRow)));
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const arg::ArgNode& n = g.nodes[i];
      const std::uint32_t first = g.level_begin[n.level];
      const int32 parent =
          n.parent < 0 ? -1 : int32(std::uint32_t(n.parent) - g.level_begin[n.level - 1u]);
      rows[i] = {n.level, int32(i - first), parent, n.a, n.mu_min, n.mu_max,
                 n.r,     n.theta,          n.phi,  n.v};
    }
    count = g.nodes.size();
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");

  InitMaterializedSRF(fcinfo, 0);
  ReturnSetInfo* rsinfo = reinterpret_cast<ReturnSetInfo*>(fcinfo->resultinfo);
  for (std::size_t i = 0; i < count; ++i) {
    const NodeRow& row = rows[i];
    Datum values[10] = {Int32GetDatum(row.level),   Int32GetDatum(row.node),
                        Int32GetDatum(row.parent),  Float4GetDatum(row.area),
                        Float4GetDatum(row.mu_min), Float4GetDatum(row.mu_max),
                        Float4GetDatum(row.r),      Float4GetDatum(row.theta),
                        Float4GetDatum(row.phi),    Float4GetDatum(row.volume)};
    bool nulls[10] = {false, false, row.parent < 0};
    tuplestore_putvalues(rsinfo->setResult, rsinfo->setDesc, values, nulls);
  }
  return (Datum)0;
}

// arg_info(arg) RETURNS jsonb
Datum arg_info(PG_FUNCTION_ARGS) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  char* json = nullptr;
  argpg::Outcome out = argpg::guarded([&] {
    const std::string_view bytes = argpg::view(value);
    json = argpg::to_cstring(describe(arg::deserialize_arg(bytes, false), bytes.size()));
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot read ARG");
  PG_RETURN_DATUM(DirectFunctionCall1(jsonb_in, CStringGetDatum(json)));
}

// arg_svg(arg, level int DEFAULT 2) RETURNS text
Datum arg_svg(PG_FUNCTION_ARGS) {
  const varlena* value = PG_GETARG_ARG_PP(0);
  const int32 level = PG_GETARG_INT32(1);
  varlena* svg = nullptr;
  argpg::Outcome out = argpg::guarded([&] {
    svg = argpg::to_varlena(
        arg::arg_graph_svg(arg::deserialize_arg(argpg::view(value), false), level));
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot draw ARG");
  PG_RETURN_TEXT_P(svg);
}

}  // extern "C"
