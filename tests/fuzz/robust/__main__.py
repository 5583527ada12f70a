"""Run a robustness campaign, or reproduce one case from its seed.

    python -m tests.fuzz.robust --seed 1 --cases 10000 --jobs 2     a campaign
    python -m tests.fuzz.robust --seed 4711 --show                  one case: its files, commands, outputs
    python -m tests.fuzz.robust --seed 4711 --show --keep /tmp/c    ... and keep its files there

Exit status 0 when no case found an internal error (or another failing kind,
see :mod:`.campaign`), 1 otherwise.  ``--kind`` restricts the campaign to one
generator (``spin-mutant``, ``spin-snippet``, ``translate``, ``image``,
``pbasic``, ``trace``, ``cli``); a finding's reproduction command names it.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
from collections import Counter

from .campaign import BAD_KINDS, Campaign, run_campaign, run_case
from .cases import KINDS, make_case


def _limit_memory(megabytes: int) -> None:
    """Cap the address space so that a runaway allocation is a MemoryError, not a swapping machine."""
    if megabytes <= 0:
        return
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (megabytes << 20, megabytes << 20))
    except (ImportError, ValueError, OSError):
        pass


def _chunk(args_tuple):
    first, count, kind, budget, memory = args_tuple
    _limit_memory(memory)
    return run_campaign(first, count, kind, budget)


def _merge(parts, first_seed) -> Campaign:
    total = Campaign(first_seed)
    for p in parts:
        total.cases += p.cases
        total.commands += p.commands
        total.statuses.update(p.statuses)
        total.kinds.update(p.kinds)
        total.kind_statuses.update(p.kind_statuses)
        total.findings.extend(p.findings)
        total.seconds = max(total.seconds, p.seconds)
    return total


def _report(camp: Campaign, args) -> str:
    lines = [f"robustness campaign: seeds {camp.first_seed}..{camp.first_seed + camp.cases - 1} "
             f"({camp.cases} cases, {camp.commands} commands, {camp.seconds:.0f} s"
             + (f", {args.jobs} jobs" if args.jobs > 1 else "") + ")",
             "cases by kind: " + ", ".join(f"{k} {n}" for k, n in sorted(camp.kinds.items())),
             "exit statuses: " + ", ".join(f"{k}: {n}" for k, n in sorted(camp.statuses.items(),
                                                                         key=lambda kv: str(kv[0])))]
    table: dict = {}
    for (kind, command, status), n in camp.kind_statuses.items():
        table.setdefault((kind, command), Counter())[status] += n
    lines.append("exit statuses by generator and command:")
    for (kind, command), c in sorted(table.items()):
        lines.append(f"  {kind:13} {command:15} " + "  ".join(f"{st}: {n}" for st, n in
                                                             sorted(c.items(), key=lambda kv: str(kv[0]))))
    counts = Counter(f.kind for f in camp.findings)
    lines.append("findings: " + (", ".join(f"{k} {n}" for k, n in sorted(counts.items())) or "none"))
    for sig, group in camp.signatures().items():
        f = group[0]
        lines.append(f"\n[{len(group)}x] {sig}")
        lines.append(f"  first seed {f.seed}: {f.reproduce()}")
        lines.append("  argv: " + " ".join(repr(a) if (" " in a or not a) else a for a in f.argv))
        tail = [ln for ln in f.detail.strip().splitlines() if ln.strip()][-3:]
        lines += ["  | " + ln[:200] for ln in tail]
    return "\n".join(lines)


def _show_case(seed: int, kind, keep, budget: float) -> int:
    case = make_case(seed, kind)
    print(f"case {seed}: {case.kind} from {case.origin}")
    for name, data in case.files.items():
        print(f"--- file {name} ({len(data)} bytes)")
        if name.endswith((".spin", ".bs2", ".bs1", ".pbasic", ".bas", ".log", ".BS2")) and len(data) < 6000:
            print(data.decode("utf-8", "backslashreplace"))

    def show(argv, status, out, err):
        print("--- $ spinemu " + " ".join(repr(a) if (" " in a or not a) else a for a in argv))
        print(f"exit status {status}")
        if out.strip():
            print(out.rstrip()[-4000:])
        if err.strip():
            print(err.rstrip()[-4000:])

    findings, _ = run_case(case, budget, workdir=keep, show=show)
    for f in findings:
        print(f"FINDING {f.signature}")
        if f.kind == "bad-python":
            print(f.detail)
    if keep:
        print(f"(files kept in {keep})")
    return 1 if any(f.kind in BAD_KINDS for f in findings) else 0


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m tests.fuzz.robust", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seed", type=int, default=1, help="first case seed (default 1)")
    p.add_argument("--cases", type=int, default=None, help="how many cases (default 1000; with --show: 1)")
    p.add_argument("--kind", choices=sorted(KINDS), help="only this generator")
    p.add_argument("--budget", type=float, default=20.0, help="CPU seconds per case (default 20)")
    p.add_argument("--jobs", type=int, default=1, help="processes (default 1)")
    p.add_argument("--memory-mb", type=int, default=3072, help="address-space cap per process (0: none)")
    p.add_argument("--show", action="store_true", help="print each case's files, commands and outputs")
    p.add_argument("--keep", metavar="DIR", help="with --show: write the case's files to DIR and keep them")
    p.add_argument("--json", metavar="FILE", help="also write the findings as JSON")
    args = p.parse_args(argv)
    if args.show:
        status = 0
        for seed in range(args.seed, args.seed + (args.cases or 1)):
            status |= _show_case(seed, args.kind, args.keep and os.path.join(args.keep, str(seed)), args.budget)
        return status
    cases = args.cases or 1000
    if args.jobs > 1:
        import multiprocessing
        step = -(-cases // args.jobs)
        chunks = [(s, min(step, args.seed + cases - s), args.kind, args.budget, args.memory_mb)
                  for s in range(args.seed, args.seed + cases, step)]
        with multiprocessing.get_context("fork").Pool(len(chunks)) as pool:
            camp = _merge(pool.map(_chunk, chunks), args.seed)
    else:
        _limit_memory(args.memory_mb)

        def progress(c, case, findings):
            if c.cases % 250 == 0 or any(f.kind in BAD_KINDS for f in findings):
                bad = len(c.bad)
                sys.stderr.write(f"\r{c.cases}/{cases} cases, {bad} failing findings   ")
                sys.stderr.flush()

        camp = run_campaign(args.seed, cases, args.kind, args.budget, progress)
        sys.stderr.write("\n")
    print(_report(camp, args))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump([f.__dict__ for f in camp.findings], fh, indent=1)
    return 1 if camp.bad else 0


if __name__ == "__main__":
    sys.exit(main())
