// The main demo: the damping coefficient alpha that gives a target restitution e, for both ends of
// contact, and what an overlap-calibrated alpha really gives in a solver that clamps forces.
#include <demcontact.h>

#include <cmath>
#include <cstdio>

int main() {
    const double ps[] = {1.0, 1.5, 2.0, 3.0};
    const double es[] = {0.1, 0.3, 0.5, 0.7, 0.9};
    std::printf("demcontact %s: damping coefficient alpha for target restitution e\n", dc_version());
    std::printf("  m d'' + alpha sqrt(m k) d^((p-1)/2) d' + k d^p = 0\n\n");
    std::printf("%5s %5s | %18s %18s | %s\n", "p", "e", "alpha (overlap end)", "alpha (force end)",
                "e realised by overlap-alpha when forces are clamped");
    int bad = 0;
    for (double p : ps) {
        for (double e : es) {
            double a_overlap = 0.0, a_force = 0.0, e_clamped = 0.0;
            int32_t s1 = dc_alpha_from_e(e, p, DC_END_OVERLAP, &a_overlap);
            int32_t s2 = dc_alpha_from_e(e, p, DC_END_FORCE, &a_force);
            int32_t s3 = dc_e_from_alpha(a_overlap, p, DC_END_FORCE, &e_clamped);
            if (s1 != DC_OK || s2 != DC_OK || s3 != DC_OK) {
                std::fprintf(stderr, "error: %s\n", dc_status_str(s1 != DC_OK ? s1 : s2 != DC_OK ? s2 : s3));
                bad++;
                continue;
            }
            std::printf("%5.2f %5.2f | %18.12f %18.12f | %.6f\n", p, e, a_overlap, a_force, e_clamped);
            if (!(a_force > a_overlap) || !(e_clamped > e)) bad++;
        }
    }
    return bad == 0 ? 0 : 1;
}
