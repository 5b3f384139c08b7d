// Running one of OpenMesh's mesh readers over bytes in memory, under a lock and without logging.
#pragma once

#include <functional>
#include <string>

#include <OpenMesh/Core/IO/Options.hh>

#include "io/memory_stream.hpp"
#include "io/soup_importer.hpp"

namespace arg::io {

enum class OpenMeshReader { Off, Obj, Ply, Stl };

// Runs OpenMesh's `reader` over `buffer` into `importer` with the requested `options` (updated
// to what the reader reports). OpenMesh's readers are process-wide singletons with mutable state,
// so calls are serialised; OpenMesh's log streams are silenced. With `fail_on_bad_read` the
// stream throws on any failed extraction (a truncated or malformed body), which becomes an
// InputError worded by `describe_failure`; arg errors thrown by the importer pass through.
// Returns the reader's own verdict.
bool run_openmesh_reader(OpenMeshReader reader, MemoryStreamBuf& buffer, SoupImporter& importer,
                         OpenMesh::IO::Options& options, bool fail_on_bad_read,
                         const std::function<std::string()>& describe_failure);

}  // namespace arg::io
