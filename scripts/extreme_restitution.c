/* The set-up exports at vanishing restitution (e = 10^-k), both end criteria: status, answer and
 * wall time of dc_dt_for_accuracy, dc_dt_for_accuracy_step_aware (Hertz, v0 = 1 m/s,
 * omega0 = 1e3, tol 0.05) and dc_plan (glass beads of 1-4 mm at 2 m/s in a 0.5 m bed, e_tol
 * 0.01). Built and run by scripts/extreme_restitution.sh; the figures quoted in
 * docs/robustness.md and in those exports' docs come from its table. */
#include <demcontact.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec a;
    clock_gettime(CLOCK_MONOTONIC, &a);
    return (double)a.tv_sec + 1e-9 * (double)a.tv_nsec;
}

int main(int argc, char **argv) {
    const int kmax = argc > 1 ? atoi(argv[1]) : 20;
    setvbuf(stdout, NULL, _IONBF, 0);
    printf("| criterion | e | dt_for_accuracy | s | step-aware | s | dc_plan (steps per contact) | s |\n");
    printf("|---|---|---|---|---|---|---|---|\n");
    for (int c = 0; c < 2; c++) {
        for (int k = 1; k <= kmax; k++) {
            double e = 1.0;
            for (int i = 0; i < k; i++) e /= 10.0;
            double dt = -1.0, dts = -1.0;
            double t0 = now();
            const int s1 = dc_dt_for_accuracy(1.5, e, c, 1.0, 1e3, 0.05, &dt);
            const double t1 = now();
            const int s2 = dc_dt_for_accuracy_step_aware(1.5, e, c, 1.0, 1e3, 0.05, &dts);
            const double t2 = now();
            dc_plan_input in;
            if (dc_plan_input_init(&in) != DC_OK) return 1;
            in.youngs = 7e10, in.poisson = 0.22, in.density = 2500.0, in.restitution = e;
            in.radius_min = 1e-3, in.radius_max = 4e-3, in.v_max = 2.0, in.depth = 0.5;
            in.overlap_tol = 0.01, in.e_tol = 0.01, in.duration_tol = 3.0, in.criterion = c;
            dc_plan_result r;
            int32_t field = -1;
            const int s3 = dc_plan(&in, &r, &field);
            const double t3 = now();
            printf("| %s | 1e-%d | ", c ? "force" : "overlap", k);
            if (s1 == DC_OK) printf("%.4g s", dt); else printf("status %d", s1);
            printf(" | %.2f | ", t1 - t0);
            if (s2 == DC_OK) printf("%.4g s", dts); else printf("status %d", s2);
            printf(" | %.2f | ", t2 - t1);
            if (s3 == DC_OK) printf("%.4g", r.steps_per_contact); else printf("status %d, field %d", s3, field);
            printf(" | %.2f |\n", t3 - t2);
        }
    }
    return 0;
}
