/* libFuzzer harness for the C ABI. The first byte selects an export, the rest is decoded into
 * doubles (raw bit patterns, so NaN, inf, subnormals and huge values all occur) and an integer.
 * Every call must return a known status (never DC_ERR_INTERNAL), leave its output untouched on
 * error and produce a finite output on success; any violation aborts, which libFuzzer reports.
 * Built and run by scripts/fuzz.sh (Rust code instrumented for coverage, ASan+UBSan on the C side). */
#include <demcontact.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define SENTINEL (-7.25e101)

static void verdict(int32_t s, double out) {
    int known = s == DC_OK || (s >= 6101 && s <= 6139);
    if (!known) abort();
    if (s == DC_OK && !isfinite(out)) abort();
    if (s != DC_OK && memcmp(&out, &(double){SENTINEL}, sizeof out) != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (size < 1) return 0;
    double x[8] = {0};
    uint8_t buf[sizeof x + 4] = {0};
    memcpy(buf, data + 1, size - 1 < sizeof buf ? size - 1 : sizeof buf);
    memcpy(x, buf, sizeof x);
    int32_t c;
    memcpy(&c, buf + sizeof x, sizeof c);
    c = (c % 4 + 4) % 4 - 1; /* -1, 0, 1, 2: valid and invalid criteria */
    double out = SENTINEL;
    switch (data[0] % 6) {
    case 0: verdict(dc_alpha_from_e(x[0], x[1], c, &out), out); break;
    case 1: verdict(dc_e_from_alpha(x[0], x[1], c, &out), out); break;
    case 2: verdict(dc_dt_crit(x[0], x[1], x[2], &out), out); break;
    case 3: verdict(dc_hertz_stiffness(x[0], x[1], x[2], x[3], x[4], x[5], &out), out); break;
    case 4: verdict(dc_effective_modulus(x[0], x[1], x[2], x[3], &out), out); break;
    case 5:
        if (!dc_status_str(c) || !dc_version()) abort();
        if (dc_alpha_from_e(x[0], x[1], c, NULL) != DC_ERR_NULL_POINTER) abort();
        break;
    }
    return 0;
}
