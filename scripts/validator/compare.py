#!/usr/bin/python3
"""relt's glTF loader against the Khronos glTF-Validator.

compare.py [options] PATH...   (PATH: a .gltf/.glb file or a folder searched for them)

For every file it runs `relt info FILE` and the validator (validate.mjs, one node process for
many files) and sorts the file into one kind:
  agree-accept              relt loads it, the validator reports no error
  agree-refuse              relt refuses it (exit 2), the validator reports errors
  relt-loads-error-render   relt loads it, the validator reports an error in data relt renders
  relt-loads-error-ignored  relt loads it, the validator's errors are all in parts relt ignores
  relt-refuses-valid        relt refuses it, the validator reports no error
  relt-crash                relt exited with something other than 0 or 2, or hung
"Loads" includes a valid file with nothing to render (no camera or emitter): `relt info` prints
its summary and exits 2, but the loader accepted it, which is what is compared here.
rendering.py decides which errors affect rendering.

Options:
  --relt PATH         the relt executable (default build/relt)
  --mutated N         also N files from mutate.py (into a temporary folder, removed afterwards)
  --seed S            mutate.py's seed (default 20240601)
  --allow-list FILE   disagreements listed there are expected; exit 1 on any other
  --report FILE       write every file's outcome as JSON lines
  --jobs J            relt runs at a time (default 8: they mostly wait for MPI start-up)
  --modules DIR       the node_modules folder holding gltf-validator (default build/validator/node_modules)
  --skip-code N       exit code when node or the validator is missing (default 3; CTest uses 77)
Exit: 0, 1 (unexpected disagreements with --allow-list), 3 or --skip-code (no node or validator).
A PATH that does not exist is left out with a note (../shared may be absent).
"""
import argparse
import collections
import concurrent.futures
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
import mutate  # noqa: E402
import rendering  # noqa: E402

AGREE = ("agree-accept", "agree-refuse")
KINDS = AGREE + ("relt-loads-error-render", "relt-loads-error-ignored", "relt-refuses-valid", "relt-crash")
# One rank, no MPI daemon: a singleton start-up takes 0.15 s instead of 0.7 s.
RELT_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMPI_MCA_pml": "ob1",
            "OMPI_MCA_btl": "self", "OMPI_MCA_ess_singleton_isolated": "1"}


def gather(paths):
    files = []
    for p in paths:
        if os.path.isdir(p):
            for folder, _, names in sorted(os.walk(p)):
                files += [os.path.join(folder, n) for n in sorted(names) if n.endswith((".gltf", ".glb"))]
        elif os.path.isfile(p):
            files.append(p)
    return files


class ValidatorMissing(Exception):
    pass


def run_validator(files, timeout=600):
    """file -> {"errors": [...], "failed": ...}; a batch that hangs is split until the culprit is alone."""
    if not files:
        return {}
    try:
        out = subprocess.run(["node", os.path.join(HERE, "validate.mjs")], input="\n".join(files) + "\n",
                             capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        if len(files) == 1:
            return {files[0]: {"errors": [{"code": "VALIDATOR_TIMEOUT", "pointer": ""}], "failed": "timeout"}}
        half = len(files) // 2
        return {**run_validator(files[:half], timeout), **run_validator(files[half:], timeout)}
    if out.returncode == 3:
        raise ValidatorMissing(out.stderr.strip())
    results = {}
    for line in out.stdout.splitlines():
        r = json.loads(line)
        results[r["file"]] = r
    missing = [f for f in files if f not in results]
    if missing and len(missing) < len(files):
        results.update(run_validator(missing, timeout))  # node died part-way: the rest again
    for f in missing:
        results.setdefault(f, {"errors": [{"code": "VALIDATOR_CRASH", "pointer": ""}], "failed": out.stderr[-200:]})
    return results


def run_relt(relt, file):
    """(outcome, message): accept, loaded (valid but nothing to render), refuse or crash."""
    # Isolated singletons all take job id 0: each needs its own session folder.
    session = tempfile.mkdtemp(prefix="relt-mpi-")
    env = dict(os.environ, OMPI_MCA_orte_tmpdir_base=session, **RELT_ENV)
    try:
        p = subprocess.run([relt, "info", file], capture_output=True, text=True, timeout=60, env=env,
                           errors="replace")
    except subprocess.TimeoutExpired:
        return "crash", "timeout after 60 s"
    finally:
        shutil.rmtree(session, ignore_errors=True)
    message = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
    if p.returncode == 0:
        return "accept", message
    if p.returncode == 2:
        # The summary on stdout means the loader accepted the file and only checkRenderable refused it.
        return ("loaded" if p.stdout.startswith("scene: ") else "refuse"), message
    return "crash", "exit %d: %s" % (p.returncode, message)


def classify(relt_outcome, errors, file):
    if relt_outcome == "crash":
        return "relt-crash", []
    loads = relt_outcome in ("accept", "loaded")
    if not errors:
        return ("agree-accept" if loads else "relt-refuses-valid"), []
    if not loads:
        return "agree-refuse", []
    doc = rendering.gltf_json(file)
    used = rendering.used_data(doc) if doc is not None else (set(), set(), set())
    verdicts = [(e["code"], e["pointer"]) + rendering.affects_rendering(e["code"], e["pointer"], doc, used)
                for e in errors]
    render = [v for v in verdicts if v[2]]
    return ("relt-loads-error-render" if render else "relt-loads-error-ignored"), render or verdicts


def read_allow_list(path):
    """[(path suffix, kind, reason)] from lines `PATH KIND REASON...`; # starts a comment."""
    entries = []
    for n, line in enumerate(open(path), 1):
        line = line.split("#", 1)[0].strip() if line.lstrip().startswith("#") else line.strip()
        if not line:
            continue
        fields = line.split(None, 2)
        if len(fields) < 3 or fields[1] not in KINDS or fields[1] in AGREE:
            sys.exit("%s:%d: expected PATH KIND REASON with a disagreeing KIND" % (path, n))
        entries.append(tuple(fields))
    return entries


def allowed(file, kind, entries):
    norm = os.path.normpath(file).replace(os.sep, "/")
    return any(k == kind and (norm == p or norm.endswith("/" + p)) for p, k, _ in entries)


def compare(files, relt, jobs):
    validator = run_validator(files)
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        relt_results = dict(zip(files, pool.map(lambda f: run_relt(relt, f), files)))
    rows = []
    for f in files:
        outcome, message = relt_results[f]
        errors = validator[f]["errors"]
        kind, details = classify(outcome, errors, f)
        rows.append({"file": f, "kind": kind, "relt": outcome, "relt_message": message,
                     "validator_errors": sorted({e["code"] for e in errors}),
                     "details": [list(d) for d in details]})
    return rows


def summarise(rows, title):
    counts = collections.Counter(r["kind"] for r in rows)
    print("%s: %d files" % (title, len(rows)))
    for k in KINDS:
        print("  %-26s %6d" % (k, counts[k]))
    codes = collections.defaultdict(collections.Counter)
    for r in rows:
        if r["kind"] not in AGREE:
            key = {d[0] for d in r["details"]} if r["details"] else {r["relt_message"].split(": ")[-1][:60]}
            for c in key:
                codes[r["kind"]][c] += 1
    for kind in KINDS:
        if codes[kind]:
            print("  %s, by code (or relt's reason):" % kind)
            for c, n in codes[kind].most_common(25):
                print("    %6d  %s" % (n, c))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("paths", nargs="*")
    ap.add_argument("--relt", default=os.path.join(ROOT, "build", "relt"))
    ap.add_argument("--mutated", type=int, default=0)
    ap.add_argument("--seed", type=int, default=20240601)
    ap.add_argument("--allow-list")
    ap.add_argument("--report")
    ap.add_argument("--jobs", type=int, default=8)
    ap.add_argument("--modules")
    ap.add_argument("--skip-code", type=int, default=3)
    args = ap.parse_args()
    if args.modules:
        os.environ["RELT_VALIDATOR_MODULES"] = os.path.abspath(args.modules)
    if shutil.which("node") is None:
        print("SKIPPED: node is not installed, so the glTF validator cannot run")
        return args.skip_code
    for p in args.paths:
        if not os.path.exists(p):
            print("note: %s does not exist; left out" % p)
    files = gather(args.paths)
    try:
        rows = compare(files, args.relt, args.jobs) if files else []
    except ValidatorMissing as e:
        print("SKIPPED: %s" % e)
        return args.skip_code
    if files:
        summarise(rows, "corpus")
    if args.mutated:
        tmp = tempfile.mkdtemp(prefix="relt-mutated-")
        try:
            mutated = mutate.write_mutations(tmp, args.mutated, args.seed)
            mrows = compare(mutated, args.relt, args.jobs)
            summarise(mrows, "mutated (seed %d)" % args.seed)
            rows += mrows
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
    if args.report:
        with open(args.report, "w") as f:
            for r in rows:
                f.write(json.dumps(r) + "\n")
    if not args.allow_list:
        return 0
    entries = read_allow_list(args.allow_list)
    unexpected = [r for r in rows if r["kind"] not in AGREE and not allowed(r["file"], r["kind"], entries)]
    for r in unexpected:
        print("UNEXPECTED %s %s: relt %s (%s); validator %s" % (r["kind"], r["file"], r["relt"], r["relt_message"],
                                                              ",".join(r["validator_errors"]) or "no errors"))
    print("%d disagreement(s) not in %s" % (len(unexpected), args.allow_list))
    return 1 if unexpected else 0


if __name__ == "__main__":
    sys.exit(main())
