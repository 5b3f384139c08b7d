// Error, interrupt and memory plumbing shared by every fmgr function (see arg_bridge.hpp).
#include "arg_bridge.hpp"

extern "C" {
#include "utils/memutils.h"
}

namespace argpg {

void record(Outcome& out, Failure failure, const char* message) noexcept {
  out.failure = failure;
  snprintf(out.message, sizeof out.message, "%s", message ? message : "");
}

void raise_if_failed(const Outcome& out, int input_errcode, const char* context) {
  switch (out.failure) {
    case Failure::None:
      return;
    case Failure::Input:
      ereport(ERROR, (errcode(input_errcode), errmsg("%s: %s", context, out.message)));
      break;
    case Failure::Incomparable:
      // Not the input's fault but how it was built: the hint says how to make it comparable.
      ereport(ERROR,
              (errcode(ERRCODE_INVALID_PARAMETER_VALUE), errmsg("%s: %s", context, out.message),
               errdetail("ARGs compare only when one builder major and minor version made both "
                         "with the same build options."),
               errhint("Rebuild the values for which arg_rebuild_needed() is true, with the "
                       "options of the others (docs/REFERENCE.md, \"Upgrading\").")));
      break;
    case Failure::Limit:
      ereport(ERROR,
              (errcode(ERRCODE_PROGRAM_LIMIT_EXCEEDED), errmsg("%s: %s", context, out.message)));
      break;
    case Failure::OutOfMemory:
      ereport(ERROR, (errcode(ERRCODE_OUT_OF_MEMORY), errmsg("out of memory"),
                      errdetail("%s: the ARG core could not allocate memory.", context)));
      break;
    case Failure::Interrupted:
      // The core stopped because a cancel or termination is pending: let PostgreSQL act on it.
      CHECK_FOR_INTERRUPTS();
      ereport(ERROR,
              (errcode(ERRCODE_QUERY_CANCELED), errmsg("canceling statement due to user request")));
      break;
    case Failure::Internal:
      ereport(ERROR, (errcode(ERRCODE_INTERNAL_ERROR),
                      errmsg("internal error in the ARG core: %s", out.message),
                      errdetail("While running: %s.", context)));
      break;
  }
}

bool stop_requested() {
  return InterruptPending && (QueryCancelPending || ProcDiePending);
}

varlena* to_varlena(std::string_view bytes) {
  if (bytes.size() > MaxAllocSize - VARHDRSZ)
    throw arg::LimitError("value of " + std::to_string(bytes.size()) + " bytes is over 1 GB");
  const Size size = VARHDRSZ + bytes.size();
  auto* result = static_cast<varlena*>(palloc_extended(size, MCXT_ALLOC_NO_OOM));
  if (!result) throw std::bad_alloc();
  SET_VARSIZE(result, size);
  std::memcpy(VARDATA(result), bytes.data(), bytes.size());
  return result;
}

char* to_cstring(std::string_view text) {
  if (text.size() >= MaxAllocSize)
    throw arg::LimitError("text of " + std::to_string(text.size()) + " bytes is over 1 GB");
  auto* result = static_cast<char*>(palloc_extended(text.size() + 1, MCXT_ALLOC_NO_OOM));
  if (!result) throw std::bad_alloc();
  std::memcpy(result, text.data(), text.size());
  result[text.size()] = '\0';
  return result;
}

void* alloc_records(std::size_t count, std::size_t record_size) {
  if (record_size == 0 || count > (MaxAllocSize - 1) / record_size)
    throw arg::LimitError(std::to_string(count) + " result rows are over 1 GB");
  void* result = palloc_extended(count * record_size + (count == 0), MCXT_ALLOC_NO_OOM);
  if (!result) throw std::bad_alloc();
  return result;
}

}  // namespace argpg
