/* libFuzzer target: the calibration exports. Cases 0-4: damping from restitution and back, the
 * critical step, Hertz stiffness and the effective modulus; 5: the status strings, the version
 * and a NULL output; 6-9: the viscoelastic calibration (e(b) by the fast tiers, b from e, beta, a
 * and the speed from e, k and gamma, e(b) by the reference integrator); 10: the elastic-plastic
 * restitution and yield speed. Inputs are eight raw
 * doubles and a criterion (fuzz_scalars). */
#define FUZZ_CASES 11
#include "fuzz_common.h"

static void fuzz_case(unsigned which, uint8_t sel, const uint8_t *data, size_t n) {
    (void)sel;
    double x[8];
    int32_t c;
    fuzz_scalars(data, n, x, &c);
    double out = SENTINEL;
    switch (which) {
    case 0: verdict(dc_alpha_from_e(x[0], x[1], c, &out), out); break;
    case 1: verdict(dc_e_from_alpha(x[0], x[1], c, &out), out); break;
    case 2: verdict(dc_dt_crit(x[0], x[1], x[2], &out), out); break;
    case 3: verdict(dc_hertz_stiffness(x[0], x[1], x[2], x[3], x[4], x[5], &out), out); break;
    case 4: verdict(dc_effective_modulus(x[0], x[1], x[2], x[3], &out), out); break;
    case 5:
        if (!dc_status_str(c) || !dc_version()) abort();
        if (dc_alpha_from_e(x[0], x[1], c, NULL) != DC_ERR_NULL_POINTER) abort();
        break;
    case 6:
        verdict(dc_viscoelastic_e(x[0], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_e_series(x[0], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_b_from_e(x[1], c, &out), out);
        break;
    case 10: /* the elastic-plastic law's restitution and yield speed */
        verdict(dc_elastic_plastic_restitution(x[0], &out), out);
        if (out != SENTINEL && !(out > 0.0 && out <= 1.0)) abort();
        out = SENTINEL;
        verdict(dc_elastic_plastic_yield_speed(x[1], x[2], x[3], x[4], &out), out);
        break;
    /* The reference integrator only for b <= 10: its cost grows with b (50 us at b = 1, 350 us
     * at b = 10 instrumented; a host calibrates against it offline, at moderate b, and the other
     * tiers cover every b). A case of its own, so that its cost does not ride on theirs. */
    case 9:
        if (!(isfinite(x[0]) && x[0] > 10.0)) verdict(dc_viscoelastic_e_reference(x[0], c, &out), out);
        break;
    case 7: {
        verdict(dc_viscoelastic_b(x[0], x[1], x[2], &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_e_of_speed(x[0], x[1], x[2], c, &out), out);
        double k = SENTINEL, g = SENTINEL;
        int32_t s = dc_viscoelastic_k_gamma(x[3], x[4], x[5], &k, &g);
        verdict(s, k);
        verdict(s, g);
        break;
    }
    case 8:
        verdict(dc_viscoelastic_beta_from_e(x[0], x[1], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_a_from_e(x[0], x[1], x[2], x[3], c, &out), out);
        out = SENTINEL;
        verdict(dc_viscoelastic_speed_for_e(x[0], x[1], c, &out), out);
        break;
    }
}
