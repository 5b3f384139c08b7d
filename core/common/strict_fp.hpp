// Included first by every source whose bits must not depend on the target (the generator, the
// marching and edge collapse it shares with the build, written meshes): no fused multiply-add.
#pragma once

// Contracting a * b + c into one fused instruction rounds once instead of twice; compilers do
// it by default wherever the target has FMA (GCC even across statements), so the same source
// would give different meshes on x86-64-v3 or ARM than on baseline x86-64. Built with
// -ffp-contract=off these pragmas change nothing.
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif
