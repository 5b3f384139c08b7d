// Running OpenMesh's OBJ reader over bytes in memory, under a lock and without logging.
#pragma once

#include <functional>
#include <string>

#include <OpenMesh/Core/IO/Options.hh>

#include "io/memory_stream.hpp"
#include "io/soup_importer.hpp"

namespace arg::io {

// Runs OpenMesh's OBJ reader over `buffer` into `importer` with the requested `options` (updated
// to what the reader reports). OpenMesh's readers are process-wide singletons with mutable state,
// so calls are serialised; OpenMesh's log streams are silenced. A broken stream becomes an
// InputError worded by `describe_failure`; arg errors thrown by the importer pass through.
// Returns the reader's own verdict.
bool run_openmesh_obj_reader(MemoryStreamBuf& buffer, SoupImporter& importer,
                             OpenMesh::IO::Options& options,
                             const std::function<std::string()>& describe_failure);

}  // namespace arg::io
