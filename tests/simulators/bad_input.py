#!/usr/bin/env python3
"""Every bad model argument ends the simulator run with its own error naming the bad value and
demcontact's status text (dc_status_str, read from the library the plugin links), never a crash,
a NaN or a silent default.

  bad_input.py --sim lammps   --plugin demcontactplugin.so [--lmp lmp]
  bad_input.py --sim liggghts --plugin libdemcontact_liggghts.so

Each case runs the simulator on a two-sphere deck with one bad value and checks: exit status != 0,
an "ERROR" line that contains the bad value (as the simulator prints it) and the expected status
text; a good deck (the control) must run to the end, so the cases cannot pass by a broken deck.
Exit 77 (ctest SKIP) when the simulator is not installed.
"""
import argparse
import ctypes
import os
import re
import subprocess
import sys
import tempfile

import harness as H

# status codes (include/demcontact.h)
NOT_POSITIVE, NEGATIVE, RESTITUTION, EXPONENT, SPEC_MODEL = 6105, 6106, 6103, 6104, 6123
POISSON = 6114
NOT_FINITE, RESULT_RANGE = 6102, 6108
STEP_UNSUPPORTED, STEP_UNREACHABLE = 6136, 6137
FULL = "hertz/material 5e6 0.5 0.3 tangential mindlin NULL 1.0 0.5 rolling sds NULL 0 0.1"
FULL_RESCALE = FULL.replace("mindlin", "mindlin_rescale")
VISCO = "hertz/material 5e6 0.5 0.3 damping viscoelastic 1 0.001 2500"


def status_texts(plugin):
    """dc_status_str of the libdemcontact the plugin is linked against."""
    out = subprocess.run(["ldd", plugin], stdout=subprocess.PIPE, text=True).stdout
    m = re.search(r"libdemcontact\.so\S*\s*=>\s*(\S+)", out)
    if not m:
        raise SystemExit("bad_input: %s does not link libdemcontact (ldd)" % plugin)
    lib = ctypes.CDLL(m.group(1))
    lib.dc_status_str.restype = ctypes.c_char_p
    lib.dc_status_str.argtypes = [ctypes.c_int32]
    return lambda code: lib.dc_status_str(code).decode()


# ------------------------------------------------------------------ LAMMPS
LAMMPS_GOOD = "hertz/material 5e6 0.5 0.3"
# (label, pair_style args, pair_coeff args after "1 1", wall args or None, bad value, status or None)
LAMMPS_CASES = [
    ("E = 0", "", "hertz/material 0 0.5 0.3", None, "E = 0", NOT_POSITIVE),
    ("E < 0", "", "hertz/material -5e6 0.5 0.3", None, "E = -5000000", NOT_POSITIVE),
    ("nu > 0.5", "", "hertz/material 5e6 0.5 0.6", None, "nu = 0.6", POISSON),
    ("nu = -1", "", "hertz/material 5e6 0.5 -1", None, "nu = -1", POISSON),
    ("e = 0", "", "hertz/material 5e6 0 0.3", None, "e = 0", RESTITUTION),
    ("e > 1", "", "hertz/material 5e6 1.5 0.3", None, "e = 1.5", RESTITUTION),
    ("e < 0 (positional form)", "", "5e6 0.3 -0.5", None, "e = -0.5", RESTITUTION),
    ("p < 1", "", "powerlaw/material 5e6 0.5 0.3 0.5", None, "exponent p = 0.5", EXPONENT),
    ("p < 1 (exponent keyword)", "", "5e6 0.3 0.5 exponent 0.9", None, "exponent p = 0.9", EXPONENT),
    ("unknown pair_coeff keyword", "", "hertz/material 5e6 0.5 0.3 frobnicate", None, "'frobnicate'", None),
    ("unknown pair_style keyword", "frobnicate", LAMMPS_GOOD, None, "'frobnicate'", None),
    ("unknown damping law", "", "hertz/material 5e6 0.5 0.3 damping tsuji", None, "'tsuji'", None),
    ("viscoelastic v_ref <= 0", "", "hertz/material 5e6 0.5 0.3 damping viscoelastic 0 0.001 2500", None,
     "v_ref = 0", NOT_POSITIVE),
    ("mu < 0", "", "hertz/material 5e6 0.5 0.3 tangential mindlin NULL 1.0 -0.5", None, "mu = -0.5", NEGATIVE),
    ("e_t > 1", "", "hertz/material 5e6 0.5 0.3 tangential mindlin NULL 1.5 0.5", None, "e_t = 1.5", RESTITUTION),
    ("mu_r < 0", "", "hertz/material 5e6 0.5 0.3 rolling sds NULL 0 -0.1", None, "mu_r = -0.1", NEGATIVE),
    ("unknown tangential model", "", "hertz/material 5e6 0.5 0.3 tangential sticky NULL 1 0.5", None,
     "'sticky'", None),
    ("wall mu < 0", "", FULL, "hertz/material 5e6 0.5 0.3 tangential mindlin NULL 1.0 -0.2 zplane -0.01 NULL",
     "mu = -0.2", NEGATIVE),
    ("wall e > 1", "", LAMMPS_GOOD, "hertz/material 5e6 1.2 0.3 zplane -0.01 NULL", "e = 1.2", RESTITUTION),
    ("wall E < 0", "", LAMMPS_GOOD, "hertz/material -1 0.5 0.3 zplane -0.01 NULL", "E = -1", NOT_POSITIVE),
    ("wall unknown keyword", "", LAMMPS_GOOD, "hertz/material 5e6 0.5 0.3 sticky zplane -0.01 NULL", "'sticky'", None),
    ("unknown carry", "", FULL + " carry spin", None, "carry 'spin'", SPEC_MODEL),
    ("carry without value", "", FULL + " carry", None, "missing value for carry", None),
    ("wall unknown carry", "", FULL, FULL + " carry projected zplane -0.01 NULL", "carry 'projected'", SPEC_MODEL),
    # fix demcontact/wall/region (wall arguments after "region:"; the deck defines region wallreg)
    ("region wall: unknown region", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.3 region nosuch",
     "region nosuch does not exist", None),
    ("region wall: no region keyword", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.3",
     "missing 'region region-ID'", None),
    ("region wall: region ID missing", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.3 region",
     "missing 'region region-ID'", None),
    ("region wall: extra argument", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.3 region wallreg 7",
     "unexpected argument '7'", None),
    ("region wall: mu < 0", "", FULL, "region:hertz/material 5e6 0.5 0.3 tangential mindlin NULL 1.0 -0.2 "
     "region wallreg", "mu = -0.2", NEGATIVE),
    ("region wall: e > 1", "", LAMMPS_GOOD, "region:hertz/material 5e6 1.2 0.3 region wallreg", "e = 1.2", RESTITUTION),
    ("region wall: E < 0", "", LAMMPS_GOOD, "region:hertz/material -1 0.5 0.3 region wallreg", "E = -1", NOT_POSITIVE),
    ("region wall: nu > 0.5", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.7 region wallreg", "nu = 0.7", POISSON),
    ("region wall: unknown keyword", "", LAMMPS_GOOD, "region:hertz/material 5e6 0.5 0.3 sticky region wallreg",
     "'sticky'", None),
    # step_exact (dc_contact_model_set_step): only the Hertz law with restitution damping has a
    # step-aware form; a restitution the explicit step cannot realise is rejected
    ("step_exact viscoelastic", "", VISCO + " step_exact", None, "step_exact rejected by demcontact",
     STEP_UNSUPPORTED),
    ("wall step_exact viscoelastic", "", LAMMPS_GOOD, VISCO + " step_exact zplane -0.01 NULL",
     "step_exact rejected by demcontact", STEP_UNSUPPORTED),
    ("step_exact e unreachable", "", "hertz/material 5e6 0.001 0.3 limit_damping step_exact", None,
     "step_exact rejected by demcontact", STEP_UNREACHABLE),
    ("step_exact power law", "", "powerlaw/material 5e6 0.5 0.3 2 step_exact", None,
     "step_exact needs the Hertz exponent 1.5 (got 2)", None),
    ("step_exact with a value", "", LAMMPS_GOOD + " step_exact on", None, "unknown keyword 'on'", None),
    ("mindlin_rescale mu < 0", "", "hertz/material 5e6 0.5 0.3 tangential mindlin_rescale NULL 1.0 -0.5", None,
     "mu = -0.5", NEGATIVE),
    ("mindlin_rescale k_t given", "", "hertz/material 5e6 0.5 0.3 tangential mindlin_rescale 1e6 1.0 0.5", None,
     "write 'tangential mindlin_rescale NULL e_t mu'", None),
    # normal laws by their registry keyword (plugins/common/demcontact_laws.h, generated)
    # the adhesive laws act beyond touching (pair loop and wall fixes; tests/simulators/adhesion.py)
    ("control: dmt (good input)", "", "hertz/material 5e6 0.5 0.3 dmt 0.01", None, None, None),
    ("control: elastic_plastic (good input)", "", "hertz/material 5e6 1 0.3 elastic_plastic 1e5", None, None,
     None),
    ("dmt w < 0", "", "hertz/material 5e6 0.5 0.3 dmt -0.1", None, "work_of_adhesion = -0.1", NEGATIVE),
    ("dmt limit_damping", "", "hertz/material 5e6 0.5 0.3 limit_damping dmt 0.01", None,
     "normal law 'dmt' is never clamped", None),
    ("elastic_plastic p_y = 0", "", "hertz/material 5e6 1 0.3 elastic_plastic 0", None, "yield_pressure = 0",
     NOT_POSITIVE),
    ("elastic_plastic e < 1", "", "hertz/material 5e6 0.5 0.3 elastic_plastic 1e5", None,
     "normal law 'elastic_plastic' takes no restitution target", None),
    ("elastic_plastic no value", "", "hertz/material 5e6 1 0.3 elastic_plastic", None,
     "missing value for yield_pressure", None),
    ("control: wall jkr (good input)", "", LAMMPS_GOOD, "hertz/material 5e6 0.5 0.3 jkr 0.01 zplane -0.01 NULL",
     None, None),
    ("wall jkr step_exact", "", LAMMPS_GOOD, "hertz/material 5e6 0.5 0.3 jkr 0.01 step_exact zplane -0.01 NULL",
     "step_exact rejected by demcontact", STEP_UNSUPPORTED),
    ("wall elastic_plastic p_y < 0", "", LAMMPS_GOOD, "hertz/material 5e6 1 0.3 elastic_plastic -1 zplane -0.01 NULL",
     "yield_pressure = -1", NOT_POSITIVE),
    ("control: jkr (good input)", "", "hertz/material 5e6 0.5 0.3 jkr 0.01", None, None, None),
    ("jkr step_exact", "", "hertz/material 5e6 0.5 0.3 jkr 0.01 step_exact", None,
     "step_exact rejected by demcontact", STEP_UNSUPPORTED),
    ("jkr w < 0", "", "hertz/material 5e6 0.5 0.3 jkr -0.1", None, "work_of_adhesion = -0.1", NOT_POSITIVE),
    ("jkr w = 0", "", "hertz/material 5e6 1 0.3 jkr 0", None, "work_of_adhesion = 0", NOT_POSITIVE),
    ("jkr no value", "", "hertz/material 5e6 0.5 0.3 jkr", None, "missing value for work_of_adhesion", None),
    ("jkr limit_damping", "", "hertz/material 5e6 0.5 0.3 limit_damping jkr 0.01", None,
     "normal law 'jkr' is never clamped", None),
    # a wall's adhesive reach (dc_contact_model_reach at the group's largest radius, at init) that
    # is not a double: DMT's d_c = (3 pi w sqrt(R)/(2 E*))^(2/3) overflows for E = 1e-300, w = 1e10
    ("wall dmt reach not finite", "", LAMMPS_GOOD, "hertz/material 1e-300 1 0.3 dmt 1e10 zplane -0.01 NULL",
     "reach at radius 0.001 (the largest of group all) is not a finite double", RESULT_RANGE),
    ("region wall: dmt reach not finite", "", LAMMPS_GOOD,
     "region:hertz/material 1e-300 1 0.3 dmt 1e10 region wallreg",
     "reach at radius 0.001 (the largest of group all) is not a finite double", RESULT_RANGE),
]

# bad values met during the run (pair_demcontact.cpp): an atom's velocity not finite (the pass
# then takes the per-contact checks, naming the contact); finite values whose contact results are
# not (heavy atoms sliding fast: the damped trial force overflows), found by the deferred checks
# after the loop, before LAMMPS integrates
LAMMPS_RUN_CASES = [  # (label, pair_coeff, deck overrides, bad value as printed, status)
    ("velocity not finite (run time)", FULL, dict(velocity=["variable big equal 1e308*10",
                                                            "velocity all set v_big 0 0"]), "atoms 1 2", NOT_FINITE),
    ("results not finite (run time)", FULL.replace("NULL 1.0", "NULL 0.5"),
     dict(density="1e30", velocity=["group one id 1", "velocity one set 0 1e300 0"]), "step 0", RESULT_RANGE),
    # a wall's reach bound follows a radius grown during the run (fix adapt: 0.001 -> 10, at the
    # setup): DMT's d_c, finite at 0.001 for E = 1e-300, w = 1e7, overflows at 10 (the walls apart:
    # the atoms beyond touching, where the DMT tail is looked for)
    ("wall dmt reach of a grown radius", LAMMPS_GOOD,
     dict(wall="hertz/material 1e-300 1 0.3 dmt 1e7 zplane -20 NULL", sphere="sphere 1",
          velocity=["variable d equal 20", "fix ad all adapt 1 atom diameter v_d"]),
     "atom 1: the adhesive law's reach at its radius 10 is not a finite double", RESULT_RANGE),
    ("region wall: dmt reach of a grown radius", LAMMPS_GOOD,
     dict(wall="region:hertz/material 1e-300 1 0.3 dmt 1e7 region wallreg", sphere="sphere 1",
          velocity=["variable d equal 20", "fix ad all adapt 1 atom diameter v_d"]),
     "atom 1: the adhesive law's reach at its radius 10 is not a finite double", RESULT_RANGE),
]


def lammps_deck(plugin, style, coeff, wall, velocity=("velocity all set 0.1 0 0",), density="2500",
                sphere="sphere"):
    L = ["units si", "atom_style " + sphere, "boundary f f f", "comm_modify vel yes",
         "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box", "create_box 1 box",
         "plugin load %s" % os.path.abspath(plugin), ("pair_style demcontact " + style).strip(),
         "pair_coeff 1 1 " + coeff,
         "create_atoms 1 single 0 0 0 units box", "create_atoms 1 single 0.00199 0 0 units box",
         "set group all diameter 0.002 density %s" % density] + list(velocity) + [
         "fix integr all nve/sphere"]
    if wall and wall.startswith("region:"):  # a region wall: the box's own faces
        L += ["region wallreg block -0.01 0.01 -0.01 0.01 -0.01 0.01 side in units box",
              "fix w all demcontact/wall/region " + wall[len("region:"):]]
    elif wall:
        L.append("fix w all demcontact/wall " + wall)
    L += ["timestep 1e-7", "thermo 100", "thermo_style custom step ke", "run 100"]
    return "\n".join(L) + "\n"


# ------------------------------------------------------------------ LIGGGHTS
LIGGGHTS_GOOD = dict(Y="5e6", nu="0.3", e="0.5", mu="0.5", mur="0.1", extra="", wall="",
                     model="model demcontact tangential demcontact rolling_friction demcontact",
                     density="2500", velocity=["velocity all set 0.1 0 0"], props=[])
FULL_SURFACE = LIGGGHTS_GOOD["model"] + " surface demcontact"

LIGGGHTS_CASES = [  # (label, overrides, bad value as printed, status)
    ("youngsModulus = 0", dict(Y="0"), "youngsModulus of type 1 = 0", NOT_POSITIVE),
    ("youngsModulus < 0", dict(Y="-5e6"), "youngsModulus of type 1 = -5e+06", NOT_POSITIVE),
    ("poissonsRatio > 0.5", dict(nu="0.6"), "poissonsRatio of type 1 = 0.6", POISSON),
    ("poissonsRatio = -1", dict(nu="-1"), "poissonsRatio of type 1 = -1", POISSON),
    ("coefficientRestitution = 0", dict(e="0"), "coefficientRestitution of types 1-1 = 0", RESTITUTION),
    ("coefficientRestitution > 1", dict(e="1.5"), "coefficientRestitution of types 1-1 = 1.5", RESTITUTION),
    ("exponent < 1", dict(extra="exponent 0.5"), "exponent (all types) of type 1 = 0.5", EXPONENT),
    ("viscoelastic without rRef", dict(extra="viscoelastic on densityRef 2500"),
     "rRef (set it with viscoelastic on) of type 1 = 0", NOT_POSITIVE),
    ("coefficientFriction < 0", dict(mu="-0.5"), "coefficientFriction = -0.5", NEGATIVE),
    ("coefficientRollingFriction < 0", dict(mur="-0.1"), "coefficientRollingFriction = -0.1", NEGATIVE),
    ("tangentialRestitution > 1", dict(extra="tangentialRestitution 1.5"), "tangentialRestitution = 1.5",
     RESTITUTION),
    ("unknown keyword", dict(extra="frobnicate on"), "'frobnicate'", None),
    ("projectionCarry not on/off", dict(extra="projectionCarry project"), "'projectionCarry' argument: "
     "unknown option or wrong keyword order: 'project'", None),
    ("wall projectionCarry not on/off", dict(wall="projectionCarry yes"), "'projectionCarry' argument: "
     "unknown option or wrong keyword order: 'yes'", None),
    # `surface demcontact` exists only with the whole contact demcontact's (LIGGGHTS' own error otherwise)
    ("surface demcontact, rolling off", dict(model="model demcontact tangential demcontact surface demcontact"),
     "Unknown surface model", None),
    ("surface demcontact, builtin tangential",
     dict(model="model demcontact tangential history surface demcontact"), "Unknown surface model", None),
    # stepExact on (dc_contact_model_set_step): Hertz with restitution damping only; a restitution the
    # explicit step cannot realise is rejected
    ("stepExact viscoelastic", dict(extra="viscoelastic on rRef 0.001 densityRef 2500 stepExact on"),
     "stepExact (types 1-1, coefficientRestitution = 0.5, timestep 1e-07) rejected by demcontact", STEP_UNSUPPORTED),
    ("wall stepExact viscoelastic", dict(wall="viscoelastic on rRef 0.001 densityRef 2500 stepExact on"),
     "stepExact (types 1-1, coefficientRestitution = 0.5, timestep 1e-07) rejected by demcontact", STEP_UNSUPPORTED),
    ("stepExact exponent 2", dict(model="model demcontact tangential history", extra="exponent 2 stepExact on"),
     "exponent (stepExact needs 1.5) of type 1 = 2", STEP_UNSUPPORTED),
    ("stepExact e unreachable", dict(e="0.001", extra="limitForce on stepExact on"),
     "stepExact (types 1-1, coefficientRestitution = 0.001, timestep 1e-07) rejected by demcontact",
     STEP_UNREACHABLE),
    ("stepExact not on/off", dict(extra="stepExact yes"), "'stepExact' argument: "
     "unknown option or wrong keyword order: 'yes'", None),
    # law KEYWORD (the registry's normal laws, plugins/common/demcontact_laws.h): a good law first
    # (runs to the end: bad None), then an unknown keyword, a parameter missing or out of range, an
    # adhesive law (not evaluated at negative overlap) and a law without a step-aware form
    ("law elastic_plastic (good, runs)", dict(extra="law elastic_plastic tangentialRescale on",
                                              props=["fix m6 all property/global yieldPressure scalar 1e5"]),
     None, None),
    ("law powerlaw (good, runs)", dict(model="model demcontact tangential history", extra="law powerlaw",
                                       props=["fix m6 all property/global p scalar 1.2",
                                              "fix m7 all property/global kN peratomtypepair 1 1e5"]), None, None),
    ("law viscoelastic (good, runs)", dict(model="model demcontact tangential history", extra="law viscoelastic",
                                           props=["fix m6 all property/global viscoA scalar 1e-5"]), None, None),
    ("law unknown", dict(extra="law hooke"), "unknown normal law 'hooke' (demcontact's laws: hertz,", None),
    ("law yieldPressure missing", dict(extra="law elastic_plastic"),
     "law elastic_plastic needs its parameter yieldPressure [Pa] (yield_pressure)", None),
    ("law yieldPressure < 0", dict(extra="law elastic_plastic",
                                   props=["fix m6 all property/global yieldPressure peratomtypepair 1 -1e5"]),
     "law elastic_plastic: yieldPressure of types 1-1 = -100000 rejected by demcontact", NOT_POSITIVE),
    ("law linear kN = 0", dict(extra="law linear", props=["fix m6 all property/global kN scalar 0"]),
     "law linear: kN of types 1-1 = 0 rejected by demcontact", NOT_POSITIVE),
    # the adhesive laws (evaluated beyond touching; tests/simulators/liggghts_adhesion.py): good decks
    # run; their parameter missing or out of range, jkr's limitForce/stepExact, and the whole-contact
    # sub-models (not evaluated beyond touching) are refused
    ("law jkr (good, runs)", dict(model="model demcontact tangential history", extra="law jkr",
                                  props=["fix m6 all property/global workOfAdhesion scalar 0.1"]), None, None),
    ("law dmt (good, runs)", dict(model="model demcontact tangential history", extra="law dmt",
                                  props=["fix m6 all property/global workOfAdhesion peratomtypepair 1 0.1"]),
     None, None),
    ("law jkr workOfAdhesion missing", dict(model="model demcontact tangential history", extra="law jkr"),
     "law jkr needs its parameter workOfAdhesion [J/m^2] (work_of_adhesion)", None),
    ("law dmt workOfAdhesion missing", dict(model="model demcontact tangential history", extra="law dmt"),
     "law dmt needs its parameter workOfAdhesion [J/m^2] (work_of_adhesion)", None),
    ("law jkr workOfAdhesion < 0", dict(model="model demcontact tangential history", extra="law jkr",
                                        props=["fix m6 all property/global workOfAdhesion scalar -0.1"]),
     "law jkr: workOfAdhesion of types 1-1 = -0.1 rejected by demcontact", NOT_POSITIVE),
    ("law dmt workOfAdhesion < 0", dict(model="model demcontact tangential history", extra="law dmt",
                                        props=["fix m6 all property/global workOfAdhesion peratomtypepair 1 -2"]),
     "law dmt: workOfAdhesion of types 1-1 = -2 rejected by demcontact", NEGATIVE),
    ("law jkr limitForce", dict(model="model demcontact tangential history", extra="law jkr limitForce on",
                                props=["fix m6 all property/global workOfAdhesion scalar 0.1"]),
     "law jkr is never clamped (DC_END_OVERLAP only): drop limitForce on", None),
    ("law jkr stepExact", dict(model="model demcontact tangential history", extra="law jkr stepExact on",
                               props=["fix m6 all property/global workOfAdhesion scalar 0.1"]),
     "stepExact with law jkr (types 1-1, timestep 1e-07) rejected by demcontact", STEP_UNSUPPORTED),
    ("law jkr tangential demcontact", dict(extra="law jkr",
                                           props=["fix m6 all property/global workOfAdhesion scalar 0.1"]),
     "demcontact with an adhesive law (law dmt, law jkr): not supported", None),
    ("law dmt wall tangential demcontact", dict(model="model demcontact tangential history", extra="law dmt",
                                                wall="law dmt",
                                                props=["fix m6 all property/global workOfAdhesion scalar 0.1"]),
     "demcontact with an adhesive law (law dmt, law jkr): not supported", None),
    # a keyword given last, its value missing (the words past the end are not read)
    ("law last word", dict(extra="law"), "while parsing 'law' argument: a normal-law keyword must follow", None),
    ("wall law last word", dict(wall="law"), "while parsing 'law' argument: a normal-law keyword must follow",
     None),
    ("exponent last word", dict(extra="exponent"), "'exponent' is the last word of the line: its value is missing",
     None),
    ("limitForce last word", dict(extra="limitForce"),
     "'limitForce' argument: unknown option or wrong keyword order: '(missing value)'", None),
    ("law law", dict(extra="law law"), "unknown normal law 'law'", None),
    ("law elastic_plastic stepExact", dict(extra="law elastic_plastic stepExact on",
                                           props=["fix m6 all property/global yieldPressure scalar 1e5"]),
     "stepExact with law elastic_plastic (types 1-1, timestep 1e-07) rejected by demcontact", STEP_UNSUPPORTED),
    ("law with exponent", dict(extra="law hertz exponent 2"), "exponent 2 is the default law's", None),
    # bad values met during the run, in the pair loop's deferred checks (friction_models_demcontact.h):
    # an atom's velocity not finite (the per-pass check of the atoms' arrays, naming the atom and
    # value); finite values whose contact results are not (heavy atoms sliding fast: the damped
    # trial force overflows), found after the loop, before LIGGGHTS integrates
    ("velocity not finite (run time)", dict(model=FULL_SURFACE, velocity=[
        "variable big equal 1e308*10", "velocity all set v_big 0 0"]), "atom 1: vx = inf", NOT_FINITE),
    ("results not finite (run time)", dict(model=FULL_SURFACE, extra="tangentialRestitution 0.5", density="1e30",
                                           velocity=[
        "group one id 1", "velocity one set 0 1e300 0"]), "step 0", RESULT_RANGE),
]


def liggghts_deck(v):
    model = (v["model"] + " " + v["extra"]).strip()
    L = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off",
         "communicate single vel yes", "units si",
         "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box", "create_box 1 box",
         "neighbor 0.0002 bin",
         "fix m1 all property/global youngsModulus peratomtype " + v["Y"],
         "fix m2 all property/global poissonsRatio peratomtype " + v["nu"],
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 " + v["e"],
         "fix m4 all property/global coefficientFriction peratomtypepair 1 " + v["mu"],
         "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 " + v["mur"]] + v["props"] + [
         "pair_style gran " + model, "pair_coeff * *",
         # the wall takes its own model settings: the plain model here
         ("fix w all wall/gran model demcontact tangential demcontact rolling_friction demcontact "
          "primitive type 1 zplane -0.01 " + v["wall"]).strip(),
         "create_atoms 1 single 0 0 0 units box", "create_atoms 1 single 0.00199 0 0 units box",
         "set group all diameter 0.002 density " + v["density"]] + v["velocity"] + [
         "fix integr all nve/sphere", "timestep 1e-7", "thermo 100", "thermo_style custom step ke",
         "run 100"]
    return "\n".join(L) + "\n"


def run(cmd, cwd, env):
    if H.which("stdbuf"):
        cmd = ["stdbuf", "-oL", "-eL"] + cmd
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    return p.returncode, p.stdout.decode("utf-8", "replace")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sim", choices=["liggghts", "lammps"], required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    a = ap.parse_args()
    workdir = os.path.abspath(a.workdir or tempfile.mkdtemp(prefix="dc_bad_"))
    os.makedirs(workdir, exist_ok=True)
    text = status_texts(os.path.abspath(a.plugin))
    if a.sim == "lammps":
        from harness import lammps as lammps_runs
        exe = lammps_runs.find_lmp(a.lmp)
        env = H.mpi_env()
        cases = [(lab, lammps_deck(a.plugin, st, co, wa), bad, code) for lab, st, co, wa, bad, code in LAMMPS_CASES]
        cases += [(lab, lammps_deck(a.plugin, "", co, kw.get("wall"), **{k: v for k, v in kw.items() if k != "wall"}),
                   bad, code) for lab, co, kw, bad, code in LAMMPS_RUN_CASES]
        # (both carry values, both Mindlin laws and step_exact accepted)
        control = lammps_deck(a.plugin, "", FULL + " carry project step_exact",
                              FULL_RESCALE + " carry rotate step_exact zplane -0.01 NULL")
        # the region wall's control: the same deck with a good region wall runs to the end
        cases.insert(0, ("control: region wall (good input)", lammps_deck(
            a.plugin, "", FULL, "region:" + FULL + " region wallreg"), None, None))
        cmd = [exe, "-in", "in.deck", "-log", "none"]
    else:
        exe, env = H.liggghts_cmd(a.plugin)
        cases = [(lab, liggghts_deck(dict(LIGGGHTS_GOOD, **ov)), bad, code) for lab, ov, bad, code in LIGGGHTS_CASES]
        control = liggghts_deck(dict(LIGGGHTS_GOOD, extra="projectionCarry on stepExact on",
                                     wall="projectionCarry off stepExact on",
                                     model=LIGGGHTS_GOOD["model"] + " surface demcontact"))
        cmd = [exe, "-in", "in.deck", "-log", "none"]
    failures = 0
    for k, (label, deck, bad, code) in enumerate([("control (good input)", control, None, None)] + cases):
        d = os.path.join(workdir, "case%02d" % k)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(deck)
        rc, out = run(cmd, d, env)
        errors = [l for l in out.splitlines() if "ERROR" in l]
        if bad is None:  # the control must run to the end, with finite energies
            ok = rc == 0 and not errors and "Loop time" in out and not re.search(r"\bnan\b", out, re.I)
            why = "ran to the end" if ok else "rc=%d, errors: %s" % (rc, errors[:1] or out[-500:])
        else:
            want = text(code) if code is not None else None
            hit = [l for l in errors if bad in l and (want is None or want in l)]
            ok = rc != 0 and bool(hit) and "Loop time" not in out
            why = hit[0].strip() if hit else "rc=%d, errors: %s" % (rc, errors[:2] or out[-500:])
        print("%-4s %-32s %s" % ("ok" if ok else "FAIL", label, why))
        failures += not ok
    print("%s: %d of %d cases failed" % (a.sim, failures, len(cases) + 1))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
