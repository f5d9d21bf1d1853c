#!/usr/bin/env python3
"""The simulator harness as a package (ctest simulators_package):

  check_package.py [DIR]     (default: this script's directory, tests/simulators)

1. no Python file under DIR touches sys.path (the scenario scripts find the package `harness` in
   their own directory, which Python puts first on sys.path when it runs a script);
2. no import cycle among DIR's own modules (scenarios and harness.*), from their import
   statements (module level and inside functions);
3. every module imports cleanly in a fresh interpreter started as a scenario script is (DIR first
   on sys.path), and importing it runs nothing (no simulator is started: the scenarios run only
   under __main__), within 30 s each;
4. harness.Lammps and harness.Liggghts implement every method of the Simulator interface.
Exits 1 naming each offending file, module or cycle.
"""
import ast
import os
import subprocess
import sys


def modules(root):
    """{module name: path} of the scenario scripts and the harness package under root."""
    out = {}
    for dirpath, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        for f in files:
            if f.endswith(".py"):
                rel = os.path.relpath(os.path.join(dirpath, f), root)[:-3].split(os.sep)
                if rel[-1] == "__init__":
                    rel = rel[:-1]
                out[".".join(rel)] = os.path.join(dirpath, f)
    return out


def imports(name, path, known):
    """The modules of `known` that the module `name` imports."""
    tree = ast.parse(open(path).read(), path)
    pkg = name if path.endswith("__init__.py") else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            cands = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = pkg.split(".") if pkg else []
                parts = parts[:len(parts) - (node.level - 1)]
                base = ".".join(parts + ([base] if base else []))
            cands = [base] + ["%s.%s" % (base, a.name) if base else a.name for a in node.names]
        else:
            continue
        for c in cands:
            # importing a.b.c imports a and a.b too; a submodule's own packages are initialised
            # before it (no cycle through them)
            parts = c.split(".")
            for k in range(1, len(parts) + 1):
                m = ".".join(parts[:k])
                if m in known and m != name and not name.startswith(m + "."):
                    found.add(m)
    return found


def cycles(graph):
    """Each import cycle once, as a list of module names."""
    out, state, stack = [], {}, []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for n in sorted(graph[m]):
            if state.get(n) == 1:
                out.append(stack[stack.index(n):] + [n])
            elif n not in state:
                visit(n)
        stack.pop()
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m)
    return out


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
    mods = modules(root)
    if "harness" not in mods:
        raise SystemExit("FAIL: no package harness (harness/__init__.py) in %s" % root)
    bad = []
    for name, path in sorted(mods.items()):
        for node in ast.walk(ast.parse(open(path).read(), path)):
            if (isinstance(node, ast.Attribute) and node.attr == "path" and isinstance(node.value, ast.Name)
                    and node.value.id == "sys"):
                bad.append("%s:%d uses sys.path" % (os.path.relpath(path, root), node.lineno))
    graph = {m: imports(m, p, mods) for m, p in mods.items()}
    for c in cycles(graph):
        bad.append("import cycle: " + " -> ".join(c))
    for name in sorted(mods):
        if name == "check_package":
            continue
        # -c runs with '' (the working directory) first on sys.path, as a script has its directory;
        # the simulators stay out of reach: an import that started one would fail or hang.
        env = dict(os.environ, PATH="/nonexistent", DC_LAMMPS_VENV="/nonexistent")
        try:
            p = subprocess.run([sys.executable, "-c", "import %s" % name], cwd=root, env=env, timeout=30,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        except subprocess.TimeoutExpired:
            bad.append("import %s did not return within 30 s" % name)
            continue
        if p.returncode != 0 or p.stdout.strip():
            bad.append("import %s: exit %d, printed: %s" % (name, p.returncode, p.stdout.strip()[-500:]))
    # the classes, looked at as a scenario sees them
    probe = ("import harness as H\n"
             "for c in (H.Lammps, H.Liggghts):\n"
             "    assert issubclass(c, H.Simulator), c\n"
             "    assert c.collision is not H.Simulator.collision, '%s does not implement collision' % c.__name__\n"
             "    assert c.name and c.log != H.Simulator.log, '%s has no name or log of its own' % c.__name__\n"
             "    assert all(callable(getattr(c, m)) for m in ('command', 'run_deck', 'pour', 'parse_thermo'))\n")
    p = subprocess.run([sys.executable, "-c", probe], cwd=root, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=30)
    if p.returncode != 0:
        bad.append("the Simulator implementations: " + p.stdout.strip()[-500:])
    for b in bad:
        print("FAIL: " + b)
    if bad:
        raise SystemExit(1)
    print("simulators_package: %d modules (%s), no sys.path edit, no import cycle, each imports cleanly; "
          "Lammps and Liggghts implement Simulator" % (len(mods), ", ".join(sorted(mods))))


if __name__ == "__main__":
    main()
