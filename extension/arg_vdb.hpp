// Loading the distance field library (arg_vdb.so, OpenVDB) only when a build needs a proxy.
#pragma once

namespace argpg {

// Registers with the core a distance field function that loads $libdir/arg_vdb on its first
// call, once per backend. Called from _PG_init.
void register_distance_field();

}  // namespace argpg
