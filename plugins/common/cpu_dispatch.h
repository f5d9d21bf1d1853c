/* Run-time CPU dispatch for the simulator plugins: which variant of a hot function to run, asked
 * once. The plugins are built for the baseline x86-64 (what a Debian LIGGGHTS runs on) and carry
 * a second variant of the functions where a wider target measured faster:
 *
 * - DC_DISPATCH_AVX2: the per-pass scan of the atoms' arrays (scan_bad_values.h), AVX2.
 * - DC_DISPATCH_V4: the LIGGGHTS plugin's contact body (friction_models_demcontact.h), compiled
 *   for x86-64-v4 (AVX-512: 32 vector registers, where the baseline spills), GCC 12 or later.
 *
 * A variant never changes a result: the plugins are built without FMA contraction
 * (-ffp-contract=off, also inside target attributes) and the scan is integer bit tests.
 * DEMCONTACT_DISPATCH=baseline in the environment forces the baseline variants (the tests compare
 * both; a user can rule the dispatch out); =avx2 rules out the x86-64-v4 body only. */
#ifndef DEMCONTACT_SIM_CPU_DISPATCH_H
#define DEMCONTACT_SIM_CPU_DISPATCH_H

#include <cstdlib>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX2__)
#define DC_DISPATCH_AVX2 1
#else
#define DC_DISPATCH_AVX2 0
#endif

/* GCC 12 or later only: clang 14 has no __builtin_cpu_supports("x86-64-v4") and ignores the
 * optimize attribute the x86-64-v4 body needs (friction_models_demcontact.h). */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && !defined(__AVX512F__)
#define DC_DISPATCH_V4 1
#else
#define DC_DISPATCH_V4 0
#endif

namespace demcontact_dispatch {
namespace {

/* DEMCONTACT_DISPATCH, the variable the library's batches read too (dc_dispatch_level):
 * "baseline" runs the baseline variants only, "avx2" nothing wider than AVX2 (here: the AVX2
 * scan, the baseline contact body), "auto" or unset whatever the CPU has. */
inline bool setting_is(const char *value)
{
    const char *v = std::getenv("DEMCONTACT_DISPATCH");
    return v && std::strcmp(v, value) == 0;
}

inline bool forced_baseline()
{
    static const bool f = setting_is("baseline");
    return f;
}

inline bool capped_avx2()
{
    static const bool f = setting_is("avx2");
    return f;
}

/* The value of DEMCONTACT_DISPATCH when it is none of the above (ignored, and said so by the
 * plugin), else NULL. */
inline const char *unknown_setting()
{
    const char *v = std::getenv("DEMCONTACT_DISPATCH");
    return v && !setting_is("baseline") && !setting_is("avx2") && !setting_is("auto") ? v : nullptr;
}

#if DC_DISPATCH_AVX2
inline bool have_avx2()
{
    static const bool h = __builtin_cpu_supports("avx2");
    return h;
}
#endif

#if DC_DISPATCH_V4
inline bool have_x86_64_v4()
{
    static const bool h = __builtin_cpu_supports("x86-64-v4");
    return h;
}
#endif

/* Whether the AVX2 / x86-64-v4 variants run here (compiled in, the CPU has it, not forced off). */
inline bool use_avx2()
{
#if DC_DISPATCH_AVX2
    return have_avx2() && !forced_baseline();
#else
    return false;
#endif
}
inline bool use_v4()
{
#if DC_DISPATCH_V4
    return have_x86_64_v4() && !forced_baseline() && !capped_avx2();
#else
    return false;
#endif
}

} // namespace
} // namespace demcontact_dispatch

#endif
