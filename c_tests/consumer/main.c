/* Minimal user program against the installed package. */
#include <demcontact.h>
#include <math.h>
#include <stdio.h>

int main(void) {
    double alpha = 0.0;
    int32_t s = dc_alpha_from_e(0.5, 1.5, DC_END_FORCE, &alpha);
    if (s != DC_OK) {
        fprintf(stderr, "dc_alpha_from_e: %s\n", dc_status_str(s));
        return 1;
    }
    double e = 0.0;
    dc_e_from_alpha(alpha, 1.5, DC_END_FORCE, &e);
    printf("demcontact %s: alpha(e=0.5, p=1.5, force end) = %.15f, back e = %.15f\n", dc_version(), alpha, e);
    return fabs(e - 0.5) < 1e-14 ? 0 : 1;
}
