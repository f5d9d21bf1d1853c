/* The duration plan through the C ABI: a plan declared on the stack, reused for many contacts,
 * agrees with dc_contact_duration (levels 3 and 4 to 1e-13; level 2 to 1e-10), and bad plans,
 * NULLs and bad inputs give their statuses with the output untouched. */
#include "check.h"
#include <demcontact.h>
#include <string.h>

int main(void) {
    const double ps[] = {1.0, 1.25, 1.5, 2.0, 3.0, 5.0};
    const double es[] = {0.01, 0.3, 0.5, 0.9, 0.999};
    for (int lv = 2; lv <= DC_LEVEL_MAX; lv++) {
        for (int i = 0; i < 6; i++) {
            dc_duration_plan plan;
            CHECK_STATUS(dc_duration_plan_init(ps[i], lv, &plan), DC_OK);
            for (int j = 0; j < 5; j++) {
                for (int crit = 0; crit <= 1; crit++) {
                    double alpha = 0.0, a = 0.0, b = 0.0;
                    CHECK_STATUS(dc_alpha_from_e(es[j], ps[i], crit, &alpha), DC_OK);
                    CHECK_STATUS(dc_contact_duration(ps[i], alpha, 0.4, 30.0, crit, &a), DC_OK);
                    CHECK_STATUS(dc_contact_duration_planned(&plan, alpha, 0.4, 30.0, crit, &b), DC_OK);
                    double tol = lv >= 3 ? 1e-13 : 1e-10;
                    CHECK(dc_rel(b, a) <= tol, "p=%g e=%g crit=%d level=%d: %.17g vs %.17g", ps[i], es[j], crit, lv, b, a);
                }
            }
        }
    }
    dc_duration_plan plan, zero;
    memset(&zero, 0, sizeof zero);
    double tau = -1.0;
    CHECK_STATUS(dc_duration_plan_init(0.5, 2, &plan), DC_ERR_EXPONENT_RANGE);
    CHECK_STATUS(dc_duration_plan_init(1.5, 9, &plan), DC_ERR_LEVEL);
    CHECK_STATUS(dc_duration_plan_init(1.5, 2, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_duration_plan_init(1.5, 2, &plan), DC_OK);
    CHECK_STATUS(dc_contact_duration_planned(&zero, 0.3, 1.0, 1.0, DC_END_FORCE, &tau), DC_ERR_PLAN);
    CHECK_STATUS(dc_contact_duration_planned(NULL, 0.3, 1.0, 1.0, DC_END_FORCE, &tau), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_contact_duration_planned(&plan, 0.3, 1.0, 1.0, DC_END_FORCE, NULL), DC_ERR_NULL_POINTER);
    CHECK_STATUS(dc_contact_duration_planned(&plan, NAN, 1.0, 1.0, DC_END_FORCE, &tau), DC_ERR_NOT_FINITE);
    CHECK_STATUS(dc_contact_duration_planned(&plan, 0.3, 1.0, 1.0, 5, &tau), DC_ERR_CRITERION);
    CHECK_STATUS(dc_contact_duration_planned(&plan, 10.0, 1.0, 1.0, DC_END_OVERLAP, &tau), DC_ERR_NO_EVENT);
    CHECK(tau == -1.0, "output untouched on error");
    return dc_check_summary("test_powerlaw_plan");
}
