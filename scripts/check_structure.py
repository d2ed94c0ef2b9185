#!/usr/bin/env python3
"""Checks the source tree against the house rules of docs/architecture.md ("Layers", "House rules").

  scripts/check_structure.py [ROOT]     (ROOT: the repository, default: this script's parent)

1. Layers: the diagrams in docs/architecture.md (fenced blocks whose first line is "<scope> (top to
   bottom)") give, per scope, one layer per line; a file may include files of its own folder and of
   folders on lower lines, never of a folder on a higher line or of a peer on the same line. Scopes:
   "top level" (app, ui, charts, core, resources), "core/", "ui/" and "charts/". Every folder that
   holds sources must be in its scope's diagram, and every folder in a diagram must exist.
2. Libraries where the architecture confines them: no Qt and no GDAL in core/, GDAL only in
   charts/s57/, Qt Charts only in ui/plots/.
3. Size: no source file in app/, core/, charts/ or ui/ over 600 lines (functions: scripts/tidy.sh).
4. One definition: unit conversion literals (1852.0 / 3600.0, 2.4477, 0.0174532..., M_PI) only in
   core/common/ (and its tests, tests/core/common/, which check them), in tests/ too (but not in
   tests/support/independent/ nor INDEPENDENT_SCORING, which share no code with the project on
   purpose); the percentile written only in core/common/percentile.h.
5. Near-comparisons in tests/: RK_COMPARE_NEAR(actual, expected, tol) from tests/support/compare_near.h,
   never QVERIFY(std::abs(...) < tol) or QVERIFY2(std::abs(...) ...), which print neither value.

Prints one line per violation ("FILE:LINE: rule: detail") and exits 1 when there is any, else 0.
scripts/structure_debt.txt may list known violations still to be paid off ("PATH RULE" per line, #
comments): they are printed as debt but do not fail; a listed entry that no longer occurs fails, so the
list only shrinks.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
SOURCE_DIRS = ["app", "core", "charts", "connections", "ui"]
MAX_FILE_LINES = 600
# Tests that score the project against an independent reference with no code of core/, not even its
# constants (see their header comments); the unit-literal rule does not apply to them.
INDEPENDENT_SCORING = {"tests/app/tst_independent_arpa.cpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')

violations = []


def report(path, line, rule, detail):
    violations.append(f"{path.relative_to(ROOT)}:{line}: {rule}: {detail}")


def read_diagrams():
    """{scope: [set of names per level, top first]} from docs/architecture.md."""
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    diagrams = {}
    for block in re.findall(r"```[a-z]*\n(.*?)```", text, flags=re.S):
        lines = block.splitlines()
        head = re.match(r"^(top level|core/|ui/|charts/) \(top to bottom\)", lines[0]) if lines else None
        if not head:
            continue
        levels = []
        for line in lines[1:]:
            names = line.split("|")[0].split()
            if names:
                levels.append(names)
        diagrams[head.group(1)] = levels
    return diagrams


def rank_table(levels):
    """name -> (rank, level index); rank 0 is the bottom."""
    table = {}
    for i, names in enumerate(reversed(levels)):
        for n in names:
            table[n] = i
    return table


def sources():
    for d in SOURCE_DIRS:
        for p in sorted((ROOT / d).rglob("*")):
            if p.suffix in (".cpp", ".h") and p.is_file():
                yield p


def test_sources():
    """tests/ sources, without tests/support/independent/: the independent truth generator shares no code
    with the project on purpose (not even core/common's constants), so its own M_PI and its own
    near-comparisons are not the project's to police."""
    independent = ROOT / "tests" / "support" / "independent"
    for p in sorted((ROOT / "tests").rglob("*")):
        if p.suffix in (".cpp", ".h") and p.is_file() and independent not in p.parents:
            yield p


def scope_folder(rel):
    """(top-level component, scope key, folder inside the scope) of a source path."""
    parts = rel.parts
    top = parts[0]
    inner = parts[1] if len(parts) > 2 else "."
    return top, f"{top}/", inner


def include_target(inc, diagrams):
    """(top-level component, folder inside it) of a project include, or None for a system header."""
    parts = inc.split("/")
    if len(parts) < 2:
        return None
    if parts[0] in ("ui", "charts"):
        return parts[0], (parts[1] if len(parts) > 2 else ".")
    if parts[0] == "resources":
        return "resources", "."
    if parts[0] == "support":  # tests/support, only for tests
        return "tests", "."
    if parts[0] in rank_table(diagrams.get("core/", [])):
        return "core", parts[0]
    return None


def check_layers(diagrams):
    for scope in ("top level", "core/", "ui/", "charts/"):
        if scope not in diagrams:
            violations.append(f"docs/architecture.md: layers: no diagram '{scope} (top to bottom)'")
    if violations:
        return
    top_rank = rank_table(diagrams["top level"])
    seen = {scope: set() for scope in ("core/", "ui/", "charts/")}
    for p in sources():
        rel = p.relative_to(ROOT)
        top, scope, folder = scope_folder(rel)
        inner = rank_table(diagrams[scope]) if scope in diagrams else None
        if inner is not None:
            seen[scope].add(folder)
            if folder not in inner:
                report(p, 1, "layers", f"folder {scope}{folder} is not in the '{scope}' diagram")
                continue
        for n, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or m.group(1) != '"':
                continue
            target = include_target(m.group(2), diagrams)
            if target is None:
                continue
            ttop, tfolder = target
            if ttop == "tests":
                report(p, n, "layers", f"{m.group(2)} is test support, not for {top}/")
                continue
            if ttop != top:
                if ttop not in top_rank or top_rank[ttop] >= top_rank.get(top, -1):
                    report(p, n, "layers", f"{top}/ includes {ttop}/ ({m.group(2)}), which is not below it")
                continue
            if inner is None or tfolder == folder:
                continue
            if tfolder not in inner:
                report(p, n, "layers", f"{m.group(2)}: folder {scope}{tfolder} is not in the diagram")
            elif inner[tfolder] >= inner[folder]:
                how = "a peer of" if inner[tfolder] == inner[folder] else "above"
                report(p, n, "layers", f"{scope}{folder} includes {m.group(2)}, {how} it")
    for scope, names in seen.items():
        for n in rank_table(diagrams[scope]):
            if n not in names:
                violations.append(f"docs/architecture.md: layers: {scope}{n} is in the diagram but holds no source")


def check_libraries():
    rules = [
        (re.compile(r"^<Q"), lambda rel: rel.parts[0] == "core", "Qt in core/"),
        (re.compile(r"^<(gdal|ogr|cpl_)"), lambda rel: rel.parts[:2] != ("charts", "s57"), "GDAL outside charts/s57/"),
        (re.compile(r"^<QtCharts|^<QChart|^<QLineSeries|^<QValueAxis"), lambda rel: rel.parts[:2] != ("ui", "plots"),
         "Qt Charts outside ui/plots/"),
    ]
    for p in sources():
        rel = p.relative_to(ROOT)
        for n, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or m.group(1) != "<":
                continue
            for pattern, applies, rule in rules:
                if pattern.match("<" + m.group(2)) and applies(rel):
                    report(p, n, "libraries", f"{rule}: <{m.group(2)}>")


def check_sizes():
    for p in sources():
        n = len(p.read_text(encoding="utf-8", errors="replace").splitlines())
        if n > MAX_FILE_LINES:
            report(p, n, "size", f"{n} lines (at most {MAX_FILE_LINES})")


def check_single_definitions():
    literals = re.compile(r"1852\.0\s*/\s*3600\.0|2\.4477|0\.0174532|\bM_PI\b")
    percentile = re.compile(r"ceil\(\s*0\.95|0\.95\s*\*\s*\(?\s*(static_cast<double>\()?\s*[a-z.]+\s*(\(\))?\s*-\s*1")
    in_tests = set(test_sources())
    for p in [*sources(), *sorted(in_tests)]:
        rel = p.relative_to(ROOT)
        # tests/core/common/ checks the definitions themselves against the literal numbers; the ARPA
        # campaign scores with constants of its own on purpose (nothing of core/ in its scoring).
        own_constants = (rel.parts[:2] == ("core", "common") or rel.parts[:3] == ("tests", "core", "common")
                         or rel.as_posix() in INDEPENDENT_SCORING)
        for n, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if not own_constants and literals.search(line):
                report(p, n, "one definition", f"unit literal outside core/common/: {line.strip()[:80]}")
            if p in in_tests:
                continue  # the percentile rule is for the project's sources
            if rel.as_posix() != "core/common/percentile.h" and percentile.search(line):
                report(p, n, "one definition", f"a percentile written out (use common/percentile.h): {line.strip()[:80]}")


def check_near_comparisons():
    """QVERIFY(std::abs(a - b) < tol) and QVERIFY2(std::abs(...) ...) in tests/, the call possibly spread
    over lines; // comments are ignored (compare_near.h names the pattern it replaces)."""
    pattern = re.compile(r"\bQVERIFY2?\(\s*std::abs\(")
    for p in test_sources():
        lines = p.read_text(encoding="utf-8", errors="replace").splitlines()
        code = "\n".join(line.split("//")[0] for line in lines)
        for m in pattern.finditer(code):
            n = code.count("\n", 0, m.start()) + 1
            report(p, n, "near compare",
                   f"use RK_COMPARE_NEAR(actual, expected, tol) (support/compare_near.h): {lines[n - 1].strip()[:80]}")


def read_debt():
    path = ROOT / "scripts" / "structure_debt.txt"
    if not path.exists():
        return set()
    entries = set()
    for line in path.read_text(encoding="utf-8").splitlines():
        line = line.split("#")[0].strip()
        if line:
            entries.add(tuple(line.split()[:2]))
    return entries


def main():
    diagrams = read_diagrams()
    check_layers(diagrams)
    check_libraries()
    check_sizes()
    check_single_definitions()
    check_near_comparisons()
    debt = read_debt()
    failing, owed = [], set()
    for v in violations:
        path, rest = v.split(":", 1)
        rule = rest.split(": ", 2)[1] if rest.count(": ") >= 1 else ""
        key = (path, rule.replace(" ", "-"))
        if key in debt:
            owed.add(key)
            print("debt:", v)
        else:
            failing.append(v)
            print(v)
    for path, rule in sorted(debt - owed):
        failing.append(f"scripts/structure_debt.txt: {path} {rule} no longer occurs: remove the entry")
        print(failing[-1])
    print(f"check_structure: {len(failing)} violation(s), {len(owed)} listed as debt")
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main())
