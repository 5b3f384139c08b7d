// The one bridge between the C++ core and PostgreSQL's error handling.
//
// Every fmgr function of the extension follows the same shape:
//
//   bytea* result = nullptr;                       // plain pointers and numbers only out here
//   argpg::Outcome out = argpg::guarded([&] {      // all C++ work, exceptions caught inside
//     result = argpg::to_varlena(arg::build_arg_bytes(...));
//   });
//   argpg::raise_if_failed(out, ERRCODE_..., "context");  // ereport after the catch has closed
//
// So no C++ exception crosses into PostgreSQL, and no C++ object with a destructor is alive when
// ereport longjmps. Inside guarded(), nothing may call ereport/elog, CHECK_FOR_INTERRUPTS or an
// erroring palloc: memory for results comes from to_varlena()/to_cstring(), which report failure
// as std::bad_alloc instead of raising.
#pragma once

// C++ and core headers come before PostgreSQL's: port.h redefines snprintf and friends, and c.h
// defines short macros (Min, Max, _) that standard and Eigen headers must not see.
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <string_view>

#include "common/errors.hpp"

extern "C" {
#include "postgres.h"

#include "fmgr.h"
#include "miscadmin.h"
#if PG_VERSION_NUM >= 160000
#include "varatt.h"  // the varlena macros left postgres.h in PostgreSQL 16
#endif
}

// The versions whose server API this glue is written and tested against (the Makefile refuses
// others before compiling; this catches a build that bypasses it).
#if PG_VERSION_NUM < 150000 || PG_VERSION_NUM >= 180000
#error "arg supports PostgreSQL 15, 16 and 17"
#endif

namespace argpg {

enum class Failure { None, Input, Incomparable, Limit, OutOfMemory, Interrupted, Internal };

// What a guarded call left behind. Plain data (no destructor), so it may outlive the try and
// still be alive when ereport longjmps.
struct Outcome {
  Failure failure = Failure::None;
  char message[512] = {};
};

void record(Outcome& out, Failure failure, const char* message) noexcept;

// Runs `work` and turns every exception into an Outcome.
template <typename Work>
Outcome guarded(Work&& work) noexcept {
  Outcome out;
  try {
    work();
  } catch (const arg::InputError& e) {
    record(out, Failure::Input, e.what());
  } catch (const arg::Incomparable& e) {
    record(out, Failure::Incomparable, e.what());
  } catch (const arg::LimitError& e) {
    record(out, Failure::Limit, e.what());
  } catch (const arg::Interrupted& e) {
    record(out, Failure::Interrupted, e.what());
  } catch (const std::bad_alloc&) {
    record(out, Failure::OutOfMemory, "out of memory");
  } catch (const std::exception& e) {
    record(out, Failure::Internal, e.what());
  } catch (...) {
    record(out, Failure::Internal, "unknown exception");
  }
  return out;
}

// Raises the recorded error, if any: `input_errcode` (22P02, 22P03 or 22023) for bad input,
// 22023 with a hint to rebuild for ARGs that cannot be compared, 54000 over a limit, 53200 out of
// memory, the cancel itself when interrupted, XX000 otherwise. `context` starts the message
// ("invalid input syntax for type arg").
void raise_if_failed(const Outcome& out, int input_errcode, const char* context);

// The core's stop callback: true once a query cancel or termination is pending.
bool stop_requested();

// Bytes of a varlena (any header form, not compressed).
inline std::string_view view(const varlena* v) {
  return {VARDATA_ANY(v), VARSIZE_ANY_EXHDR(v)};
}

// Copies bytes into a new palloc'd varlena (bytea or arg). Safe inside guarded(): throws
// std::bad_alloc or arg::LimitError instead of raising.
varlena* to_varlena(std::string_view bytes);

// Copies text into a new palloc'd C string; safe inside guarded() like to_varlena.
char* to_cstring(std::string_view text);

// palloc'd, uninitialised memory for `count` plain records (rows of a set-returning function);
// safe inside guarded() like to_varlena.
void* alloc_records(std::size_t count, std::size_t record_size);

}  // namespace argpg

// The `arg` type is a plain varlena; this gets it detoasted (short header allowed).
#define PG_GETARG_ARG_PP(n) ((varlena*)PG_DETOAST_DATUM_PACKED(PG_GETARG_DATUM(n)))
