// The `arg` type's input and output: lossless text ("arg1:" + base64) and the binary form as bytes.
#include "graph/serialize.hpp"

#include "arg_bridge.hpp"

extern "C" {
#include "libpq/pqformat.h"

PG_FUNCTION_INFO_V1(arg_in);
PG_FUNCTION_INFO_V1(arg_out);
PG_FUNCTION_INFO_V1(arg_recv);
PG_FUNCTION_INFO_V1(arg_send);

// Text to arg: decodes and validates as strictly as arg_recv.
Datum arg_in(PG_FUNCTION_ARGS) {
  const char* input = PG_GETARG_CSTRING(0);
  varlena* result = nullptr;
  argpg::Outcome out =
      argpg::guarded([&] { result = argpg::to_varlena(arg::arg_from_text(input)); });
  argpg::raise_if_failed(out, ERRCODE_INVALID_TEXT_REPRESENTATION,
                         "invalid input syntax for type arg");
  PG_RETURN_POINTER(result);
}

Datum arg_out(PG_FUNCTION_ARGS) {
  varlena* value = PG_GETARG_ARG_PP(0);
  char* result = nullptr;
  argpg::Outcome out =
      argpg::guarded([&] { result = argpg::to_cstring(arg::arg_to_text(argpg::view(value))); });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot output arg value");
  PG_RETURN_CSTRING(result);
}

// Binary input: the bytes of the binary form, validated before they are stored.
Datum arg_recv(PG_FUNCTION_ARGS) {
  StringInfo buf = (StringInfo)PG_GETARG_POINTER(0);
  const char* bytes = buf->data + buf->cursor;
  const int size = buf->len - buf->cursor;
  argpg::Outcome out = argpg::guarded(
      [&] { arg::validate_arg_bytes(std::string_view(bytes, static_cast<std::size_t>(size))); });
  argpg::raise_if_failed(out, ERRCODE_INVALID_BINARY_REPRESENTATION,
                         "invalid binary input for type arg");
  bytea* result = (bytea*)palloc(VARHDRSZ + size);
  SET_VARSIZE(result, VARHDRSZ + size);
  pq_copymsgbytes(buf, VARDATA(result), size);
  PG_RETURN_BYTEA_P(result);
}

Datum arg_send(PG_FUNCTION_ARGS) {
  varlena* value = PG_GETARG_ARG_PP(0);
  StringInfoData buf;
  pq_begintypsend(&buf);
  pq_sendbytes(&buf, VARDATA_ANY(value), VARSIZE_ANY_EXHDR(value));
  PG_RETURN_BYTEA_P(pq_endtypsend(&buf));
}

}  // extern "C"
