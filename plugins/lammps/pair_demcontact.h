/* pair_style demcontact: see pair_demcontact.cpp. */
#ifndef DEMCONTACT_LAMMPS_PAIR_H
#define DEMCONTACT_LAMMPS_PAIR_H

#include "pair.h"

#include "dc_coeff.h"
#include "fix_demcontact_history.h"

#include <vector>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class PairDemcontact : public Pair {
public:
    explicit PairDemcontact(LAMMPS *lmp);
    ~PairDemcontact() override;
    void settings(int narg, char **arg) override;
    void coeff(int narg, char **arg) override;
    void init_style() override;
    double init_one(int i, int j) override;
    void reset_dt() override;
    void compute(int eflag, int vflag) override;

    /* The force loop compiled for one evaluation S (demcontact_shaped.h: a Shape, the per-contact
       body inlined into the loop, or Generic, through contact_eval); chosen by build_models. */
    template <class S>
    void compute_loop();
    typedef void (PairDemcontact::*Loop)();
    struct LoopOf {
        typedef Loop type;
        template <class S>
        static type get()
        {
            return &PairDemcontact::compute_loop<S>;
        }
    };

private:
    int n1() const { return atom->ntypes + 1; }
    void allocate();
    void build_models();
    void map_slots();
    int heal_from_partner(int i, int si, int j, int sj);

    Loop loop = &PairDemcontact::compute_loop<demcontact_shaped::Generic>;
    bool clamp = false;
    bool newton = true; // newton-on neighbour list (force->newton_pair), else newton off
    int maxpartner = 32;
    int nh = 0;
    Coeff *coeffs = nullptr; // (ntypes+1)^2, [i*(ntypes+1)+j], i <= j given or mixed
    Model *models = nullptr;  // calibrated model per type pair [type1*(ntypes+1)+type2], both orders
    double *onerad = nullptr; // largest radius per type (present and future particles)
    // adhesive laws (dmt, jkr): how far beyond touching each type pair's law acts at the types'
    // largest radii [type1*(ntypes+1)+type2] (0: overlapping pairs only), and whether any does
    double *reach = nullptr;
    bool adhesive = false;
    FixDemcontactHistory *history = nullptr;
    // history slots of every neighbour-list pair (owner i's, owner j's or -1), cached by map_slots()
    std::vector<int> pofs;  // pair index of list entry ii's first neighbour
    std::vector<int> pslot; // 2 per pair
    bigint mapped_ncalls = -1, mapped_generation = -1;
    const NeighList *mapped_list = nullptr;
};

} // namespace demcontact_lammps

#endif
