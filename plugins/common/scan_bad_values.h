/* One flag over a simulator's per-atom array: whether any value is not finite, or (positive) not
 * > 0. The LIGGGHTS plugin's begin_pass scans velocities, spins, radii and masses with it once per
 * pair pass, instead of checking each contact's state (friction_models_demcontact.h).
 *
 * On the bits u of each value, in the sign bit of an OR over the values: (u & exponent field) +
 * its lowest bit carries into the sign bit exactly when the field is all ones (inf, NaN); for
 * positive also u itself (the sign: a negative value or -0) and u - 1 (+0 wraps to all ones).
 * Integer operations only, so the compiler vectorises the loops (a floating-point sum or a
 * comparison flag it did not), and every variant gives the same answer.
 *
 * Two variants of the same loop on x86-64: baseline (SSE2, 2 values per operation) and AVX2 (4),
 * the AVX2 one used when the CPU has it (cpu_dispatch.h: asked once). The scan was 1.6 % of the
 * plugin's settled-bed time with SSE2 and 0.7 % with AVX2 (perf, docs/simulators.md). ctest
 * sim_scan_bad_values checks both variants against std::isfinite and > 0. */
#ifndef DEMCONTACT_SIM_SCAN_BAD_VALUES_H
#define DEMCONTACT_SIM_SCAN_BAD_VALUES_H

#include <cstdint>
#include <cstring>

#include "cpu_dispatch.h"

namespace demcontact_scan {
namespace {

/* The loops, inlined into each variant (compiled there for that variant's target). */
__attribute__((always_inline)) inline int bad_values_body(const double *x, int n, bool positive)
{
    const uint64_t exp = 0x7ff0000000000000ull, low = 0x0010000000000000ull;
    uint64_t bad = 0;
    if (positive)
        for (int k = 0; k < n; k++) {
            uint64_t u;
            std::memcpy(&u, &x[k], sizeof u);
            bad |= u | (u - 1) | ((u & exp) + low);
        }
    else
        for (int k = 0; k < n; k++) {
            uint64_t u;
            std::memcpy(&u, &x[k], sizeof u);
            bad |= (u & exp) + low;
        }
    return (bad >> 63) != 0;
}

/* The build's own target (baseline x86-64: SSE2). */
inline int bad_values_baseline(const double *x, int n, bool positive) { return bad_values_body(x, n, positive); }

#if DC_DISPATCH_AVX2
__attribute__((target("avx2"))) inline int bad_values_avx2(const double *x, int n, bool positive)
{
    return bad_values_body(x, n, positive);
}
#endif

/* 1 when one of x[0..n) is not finite or (positive) not > 0; 0 otherwise (and for n <= 0). */
inline int bad_values(const double *x, int n, bool positive)
{
#if DC_DISPATCH_AVX2
    if (demcontact_dispatch::use_avx2()) return bad_values_avx2(x, n, positive);
#endif
    return bad_values_baseline(x, n, positive);
}

} // namespace
} // namespace demcontact_scan

#endif
