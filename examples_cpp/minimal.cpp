#include <demcontact.hpp>
#include <cstdio>

int main() {
    namespace dc = demcontact;
    // Hertz contact (p = 1.5) in a solver that clamps attractive forces: force-zero criterion.
    double alpha = dc::alpha_from_e(0.5, 1.5, dc::criterion::force);
    std::printf("alpha = %.15f\n", alpha);
    try {
        dc::alpha_from_e(1.5, 1.5, dc::criterion::force);  // e > 1: throws
    } catch (const dc::error& err) {
        std::printf("rejected: %s (status %d)\n", err.what(), static_cast<int>(err.code()));
        return 0;
    }
    return 1;
}
