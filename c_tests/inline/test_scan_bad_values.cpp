// ctest sim_scan_bad_values: the LIGGGHTS plugin's per-pass scan (plugins/common/scan_bad_values.h),
// every variant this CPU runs, against std::isfinite and > 0: each special value at every position
// of arrays of every length up to 40 (the vector loops' bodies and tails), and random arrays of
// finite values, with and without one bad value.
#include "scan_bad_values.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

int reference(const double *x, int n, bool positive)
{
    for (int k = 0; k < n; k++)
        if (!std::isfinite(x[k]) || (positive && !(x[k] > 0.0))) return 1;
    return 0;
}

typedef int (*Scan)(const double *, int, bool);

long failures = 0, checks = 0;

void check(const char *name, Scan scan, const std::vector<double> &v, int n, bool positive)
{
    const int got = scan(v.data(), n, positive), want = reference(v.data(), n, positive);
    checks++;
    if (got != want && failures++ < 20) {
        std::printf("FAIL %s: n = %d, positive = %d: %d, expected %d; values:", name, n, (int)positive, got, want);
        for (int k = 0; k < n; k++) std::printf(" %g", v[k]);
        std::printf("\n");
    }
}

std::uint64_t rng = 0x9e3779b97f4a7c15ull;
double uniform()
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (rng >> 11) * (1.0 / 9007199254740992.0);
}

void run(const char *name, Scan scan, int random_arrays)
{
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    const double specials[] = {inf, -inf, nan, -nan, 0.0, -0.0, -1.0, -1e-300, -5e-324, 5e-324,
                               2.2250738585072014e-308, 1.7976931348623157e308, -1.7976931348623157e308, 1.0};
    const long before = failures, checks_before = checks;
    for (int n = 0; n <= 40; n++)
        for (double s : specials)
            for (int pos = 0; pos < (n ? n : 1); pos++)
                for (int positive = 0; positive < 2; positive++) {
                    std::vector<double> v(n + 1, 0.5); // one value past n: never read as part of x
                    v[n] = nan;
                    if (n) v[pos] = s;
                    check(name, scan, v, n, positive != 0);
                }
    for (int r = 0; r < random_arrays; r++) {
        const int n = 1 + (int)(uniform() * 3000);
        std::vector<double> v(n);
        for (double &x : v) x = std::ldexp(0.5 + uniform(), (int)(uniform() * 2000) - 1000) * (uniform() < 0.5 ? -1 : 1);
        for (int positive = 0; positive < 2; positive++) {
            std::vector<double> w(v);
            if (positive)
                for (double &x : w) x = std::fabs(x);
            check(name, scan, w, n, positive != 0);
            w[(size_t)(uniform() * n)] = (r % 3 == 0) ? nan : (r % 3 == 1 ? -inf : (positive ? -0.0 : inf));
            check(name, scan, w, n, positive != 0);
        }
    }
    std::printf("%s: %ld cases checked, %ld failed\n", name, checks - checks_before, failures - before);
}

} // namespace

int main(int argc, char **argv)
{
    const int random_arrays = argc > 1 ? std::atoi(argv[1]) : 2000;
    using namespace demcontact_scan;
    run("baseline", bad_values_baseline, random_arrays);
#if DC_DISPATCH_AVX2
    if (demcontact_dispatch::have_avx2())
        run("avx2", bad_values_avx2, random_arrays);
    else
        std::printf("avx2 variant: not run (this CPU has no AVX2); the plugin uses the baseline one here\n");
#else
    std::printf("one variant only in this build (not x86-64 GCC/Clang, or AVX2 already the baseline)\n");
#endif
    run("dispatched", bad_values, random_arrays);
    std::printf("%s\n", failures ? "FAILED" : "passed");
    return failures ? 1 : 0;
}
