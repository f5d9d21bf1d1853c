/* libFuzzer target: the builtin corrections. Every builtin model code (and unknown ones), clamp
 * and wall flag: value -> realised e round trip to 1e-9, realised e in [0, 1]; the YADE
 * viscoelastic cn; the LAMMPS release choice (any int32 date: a LAMMPS code out, stable under a
 * second call, the output untouched on error). Inputs are 8 selector bytes and 24 raw doubles. */
#define FUZZ_CASES 1
#include "fuzz_common.h"

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    (void)which, (void)sel;
    uint8_t d[8 + sizeof(double) * 24]; /* 8 selector bytes, then 24 doubles */
    fuzz_take(d, sizeof d, data, n);
    double y[24];
    memcpy(y, d + 8, sizeof y);
    int32_t model = (int32_t)(d[0] % 13) - 1; /* -1 .. 11: every DC_BUILTIN_* and unknown codes */
    int32_t clamp = (int32_t)(d[1] % 4) - 1, wall = (int32_t)(d[2] % 4) - 1; /* -1, 0, 1, 2 */
    double out = SENTINEL, back = SENTINEL;
    int32_t s;
    /* value to type, and its forward map: the round trip must give e back */
    s = dc_builtin_value_for_e(model, clamp, y[0], &out);
    verdict(s, out);
    if (s == DC_OK) {
        s = dc_builtin_realised_e(model, clamp, out, &back);
        if (s != DC_OK || !(fabs(back - y[0]) <= 1e-9)) abort();
    }
    out = SENTINEL, back = SENTINEL;
    s = dc_builtin_value_for_e_wall(model, clamp, wall, y[0], &out);
    verdict(s, out);
    if (s == DC_OK) {
        s = dc_builtin_realised_e_wall(model, clamp, wall, out, &back);
        if (s != DC_OK || !(fabs(back - y[0]) <= 1e-9)) abort();
    }
    out = SENTINEL;
    s = dc_builtin_realised_e(model, clamp, y[1], &out);
    verdict(s, out);
    if (s == DC_OK && !(out >= 0.0 && out <= 1.0)) abort();
    out = SENTINEL;
    s = dc_builtin_realised_e_wall(model, clamp, wall, y[1], &out);
    verdict(s, out);
    if (s == DC_OK && !(out >= 0.0 && out <= 1.0)) abort();
    out = SENTINEL;
    verdict(dc_builtin_yade_viscel_cn(y[2], y[3], y[4], &out), out);
    /* the release: half the inputs a date near the known ones, the rest any int32 */
    int32_t date;
    memcpy(&date, d + 4, sizeof date);
    if (d[3] & 1) date = 20220101 + (int32_t)((uint32_t)date % 60000u);
    int32_t code = INT32_MIN, again = INT32_MIN;
    s = dc_builtin_for_lammps_release(model, date, &code);
    if (!known(s)) abort();
    if (s != DC_OK && code != INT32_MIN) abort();
    if (s == DC_OK) {
        if (!(code == DC_BUILTIN_LAMMPS_COEFF_RESTITUTION || code == DC_BUILTIN_LAMMPS_TSUJI_HERTZ ||
              code == DC_BUILTIN_LAMMPS_TSUJI_HOOKE || code == DC_BUILTIN_LAMMPS_TSUJI_HERTZ_SQRT2 ||
              code == DC_BUILTIN_LAMMPS_TSUJI_HOOKE_SQRT2))
            abort();
        if (dc_builtin_for_lammps_release(code, date, &again) != DC_OK || again != code) abort();
    }
}
