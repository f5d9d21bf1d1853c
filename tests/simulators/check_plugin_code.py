#!/usr/bin/env python3
"""ctest liggghts_plugin_code: what the compiler made of the plugin, read from its disassembly.

- No fused multiply-add anywhere (vfmadd..., vfmsub..., vfnmadd..., vfnmsub...): the plugins are built
  with -ffp-contract=off, which must hold in the functions compiled for x86-64-v4 too. The dump
  comparisons cannot see a contraction there (the header's products are barrier-protected, and the
  plugin's own ones by +-1 are exact), so this reads the code itself.
- No 512-bit instruction (a zmm register): the x86-64-v4 contact body is meant to be scalar and
  at most 256-bit code, which does not lower an Intel core's clock.
- With --expect-v4: the x86-64-v4 bodies are there (a build with run-time dispatch).

Usage: check_plugin_code.py PLUGIN.so [--expect-v4 | --native]. Exit 0 pass, 1 fail, 77 skipped (not x86-64,
or no objdump).
"""
import argparse
import platform
import re
import shutil
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("plugin")
    ap.add_argument("--expect-v4", action="store_true")
    ap.add_argument("--native", action="store_true",
                    help="a -march=native build: only the FMA check (512-bit code is the host's choice)")
    a = ap.parse_args()
    if platform.machine() not in ("x86_64", "AMD64"):
        print("SKIPPED: liggghts_plugin_code (not x86-64: %s)" % platform.machine())
        return 77
    objdump = shutil.which("objdump")
    if not objdump:
        print("SKIPPED: liggghts_plugin_code (no objdump)")
        return 77
    p = subprocess.run([objdump, "-d", "-C", "--no-show-raw-insn", a.plugin], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True)
    if p.returncode != 0:
        print("FAIL: objdump exited with %d: %s" % (p.returncode, p.stderr.strip()))
        return 1
    fn, fma, wide, v4 = None, {}, {}, set()
    for line in p.stdout.splitlines():
        m = re.match(r"^[0-9a-f]+ <(.*)>:$", line)
        if m:
            fn = m.group(1)
            if "intersect_with_v4<" in fn:
                v4.add(fn)
            continue
        if "\t" not in line:
            continue
        insn = line.split("\t", 1)[1]
        if re.match(r"vfn?m(add|sub)", insn):
            fma[fn] = fma.get(fn, 0) + 1
        if "%zmm" in insn:
            wide[fn] = wide.get(fn, 0) + 1
    ok = True
    for what, found in (("fused multiply-add", fma),) + ((("512-bit (zmm)", wide),) if not a.native else ()):
        if found:
            ok = False
            print("FAIL: %d %s instructions in %d functions, e.g. %s" %
                  (sum(found.values()), what, len(found), sorted(found)[0][:160]))
        else:
            print("no %s instructions" % what)
    if a.expect_v4:
        if v4:
            print("%d contact bodies compiled for x86-64-v4" % len(v4))
        else:
            ok = False
            print("FAIL: no contact body compiled for x86-64-v4 (intersect_with_v4) in a build with run-time dispatch")
    print("passed" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
