// arg_generate_model: a closed mesh from the core's deterministic generator, as OFF bytes, so
// that tests, examples and benchmarks can make fixtures in SQL without reading files.
#include <algorithm>

#include "gen/generate_models.hpp"
#include "io/write_mesh.hpp"

#include "arg_bridge.hpp"

namespace {

constexpr int kMinResolution = 8, kMaxResolution = 128;
constexpr int kMaxVariant = 999999;

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_generate_model);

// arg_generate_model(class text, variant int, resolution int DEFAULT 32) RETURNS bytea
Datum arg_generate_model(PG_FUNCTION_ARGS) {
  const varlena* label = PG_GETARG_TEXT_PP(0);
  const int32 variant = PG_GETARG_INT32(1);
  const int32 resolution = PG_GETARG_INT32(2);
  if (variant < 0 || variant > kMaxVariant)
    ereport(ERROR,
            (errcode(ERRCODE_INVALID_PARAMETER_VALUE),
             errmsg("cannot generate model: variant %d is not in [0, %d]", variant, kMaxVariant)));
  if (resolution < kMinResolution || resolution > kMaxResolution)
    ereport(ERROR, (errcode(ERRCODE_INVALID_PARAMETER_VALUE),
                    errmsg("cannot generate model: resolution %d is not in [%d, %d]", resolution,
                           kMinResolution, kMaxResolution)));
  varlena* result = nullptr;
  argpg::Outcome out = argpg::guarded([&] {
    const std::string name(argpg::view(label));
    const std::vector<std::string> classes = arg::generator_classes();
    if (std::find(classes.begin(), classes.end(), name) == classes.end()) {
      std::string known;
      for (const std::string& c : classes) known += (known.empty() ? "" : ", ") + c;
      throw arg::InputError("unknown model class \"" + name + "\" (expected one of " + known + ")");
    }
    result = argpg::to_varlena(arg::write_off(arg::generate_model(name, variant, resolution).mesh));
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot generate model");
  PG_RETURN_BYTEA_P(result);
}

}  // extern "C"
