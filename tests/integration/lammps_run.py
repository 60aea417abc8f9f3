"""Run LAMMPS decks and read their output, for the integration tests of hardcontact.

Standard library + numpy only. Typical use in a test script:

    import lammps_run as lr

    args = lr.test_args(__doc__)            # --lmp, --np, --workdir (what ctest passes)
    res = lr.run_deck(args.lmp, DECK, args.np, args.workdir, variables={"seed": 42})
    lr.check(res.thermo[-1]["Step"][-1] == 100, "run reached step 100")
    frames = lr.read_dump(res.path("dump.atoms"))

A failed run (non-zero exit, timeout) raises LammpsRunError with the ERROR lines and the
tail of the output, unless expect_error=True, which instead requires a failure.
"""

import argparse
import glob
import gzip
import os
import shutil
import signal
import subprocess
import sys
import time
from collections import namedtuple
from pathlib import Path

import numpy as np

__all__ = [
    "Host", "liggghts_deck", "RunResult", "LammpsRunError", "run_deck", "parse_thermo", "read_dump", "read_dump_local",
    "DumpFrame", "test_args", "fresh_workdir", "check", "main",
]

DEFAULT_TIMEOUT = 600.0
_MARKER = ".lammps_run_workdir"
_REPO = Path(__file__).resolve().parents[2]


class Host(str):
    """The LAMMPS a deck runs in: the path of its executable (a str, so it can be used as one)
    plus how the fix gets into it.

    name    "launcher": build/lmp_hardcontact (Debian's LAMMPS 29 Sep 2021, fix registered);
            "modern":   a modern lmp with the PLUGIN package; every deck is run with
                        `plugin load <plugin>` as its first line, as a user's deck would be;
            "liggghts": build/liggghts_hardcontact (Debian's LIGGGHTS 3.8, fix registered);
                        decks are rewritten where LIGGGHTS needs other commands (liggghts_deck)
    plugin  path of hardcontactplugin.so for "modern", None otherwise
    """

    def __new__(cls, exe, name="launcher", plugin=None):
        self = super().__new__(cls, str(exe))
        self.name = name
        self.plugin = str(Path(plugin).resolve()) if plugin else None
        return self

    @property
    def rewrites(self):
        """True when deck_text may change a deck (it must then run from a copy)."""
        return self.plugin is not None or self.name == "liggghts"

    def deck_text(self, text):
        """The deck as this host runs it."""
        if self.name == "liggghts":
            return liggghts_deck(text)
        if not self.plugin:
            return text
        return "plugin load %s\n%s" % (self.plugin, text)


# dump custom columns LAMMPS writes as integers (the rest as floating point)
_INT_DUMP_COLUMNS = {"id", "type", "mol", "proc", "procp1", "ix", "iy", "iz", "index"}


def liggghts_deck(text):
    """A LAMMPS deck of the tests as LIGGGHTS 3.8 runs it. Five commands differ, nothing else:
      * `newton off` first: LIGGGHTS's granular neighbour lists hold a pair across processors
        on both only with newton off, which the fix requires there (as pair gran with history
        does; LIGGGHTS decks set it by convention);
      * `dump_modify ID format float F`: LIGGGHTS (LAMMPS of 2013) takes one format for the
        whole line, built here from the dump's columns (integers %d, the rest F);
      * `comm_modify KEYWORDS` is `communicate single KEYWORDS` there (vel yes, cutoff X);
      * `set ... omega 0 0 0` is left out (LIGGGHTS's set has no omega; atoms start without
        spin); a deck setting a nonzero spin that way cannot run there (LammpsRunError);
      * `compute ID group stress/atom NULL ...` loses its NULL (LIGGGHTS's stress/atom takes
        no temperature ID) and `compute ID all pressure NULL ...` takes thermo_temp instead
        (LIGGGHTS's pressure requires one; with the virial keyword it is not used).
    Everything else (atom_style sphere, read_data, other computes, restarts) LIGGGHTS reads as LAMMPS
    does."""
    columns = {}
    out = ["newton          off    # added for LIGGGHTS (lammps_run.liggghts_deck)"]
    for line in text.splitlines():
        words = line.split()
        if len(words) >= 7 and words[0] == "dump" and words[3] in ("custom", "local"):
            # dump ID group style N file columns...
            columns[words[1]] = [w for w in words[6:] if not w.startswith("#")]
        if words[:1] == ["comm_modify"]:
            line = " ".join(["communicate", "single"] + words[1:])
        if len(words) >= 5 and words[0] == "compute" and words[4:5] == ["NULL"]:
            if words[3] == "stress/atom":
                line = " ".join(words[:4] + words[5:])
            elif words[3] == "pressure":
                line = " ".join(words[:4] + ["thermo_temp"] + words[5:])
        if words[:1] == ["set"] and "omega" in words:
            k = words.index("omega")
            spin = words[k + 1:k + 4]
            if len(words) != k + 4 or any(float(w) != 0.0 for w in spin):
                raise LammpsRunError("LIGGGHTS 3.8's set has no omega (spins come only from a "
                                     "data file): cannot run '%s' there" % line.strip())
            continue    # zero spins: what every LIGGGHTS atom starts with

        if len(words) >= 5 and words[0] == "dump_modify" and "format" in words:
            k = words.index("format")
            if k + 2 < len(words) and words[k + 1] == "float" and words[1] in columns:
                fmt = " ".join("%d" if c in _INT_DUMP_COLUMNS else words[k + 2]
                               for c in columns[words[1]])
                words[k:k + 3] = ["format", '"%s"' % fmt]
                line = " ".join(words)
        out.append(line)
    return "\n".join(out) + "\n"


class LammpsRunError(RuntimeError):
    """LAMMPS did not do what the test expected (failed, timed out, or succeeded when an
    error was expected). The message holds the command, the ERROR lines and output tails."""


class RunResult:
    """What one LAMMPS run left behind.

    returncode  exit status (negative: killed by that signal; None: timed out)
    log         text of log.lammps ('' if LAMMPS never opened it)
    stdout, stderr
    thermo      list, one entry per thermo block (one per run/minimize): dict column name ->
                numpy array (int64 for integer columns such as Step/Atoms, float64 otherwise)
    errors      'ERROR...' lines (log, stdout and stderr, in that order, without duplicates)
    warnings    'WARNING...' lines, likewise
    workdir     Path the deck ran in; cmd: the command line; seconds: wall time
    """

    def __init__(self, cmd, workdir, returncode, stdout, stderr, log, seconds, timed_out):
        self.cmd = cmd
        self.workdir = Path(workdir)
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.log = log
        self.seconds = seconds
        self.timed_out = timed_out
        self.thermo = parse_thermo(log if log else stdout)
        self.errors = _grep_lines("ERROR", log, stdout, stderr)
        self.warnings = _grep_lines("WARNING", log, stdout, stderr)

    def path(self, name):
        """Path of an output file of the run (relative to its working directory)."""
        return self.workdir / name

    def thermo_last(self, column, block=-1):
        """Last value of a thermo column in a block (default: the last block)."""
        return self.thermo[block][column][-1]

    def summary(self, tail=40):
        lines = [
            "command: " + " ".join(str(c) for c in self.cmd),
            "workdir: %s" % self.workdir,
            "exit status: %s%s" % (self.returncode, " (timed out)" if self.timed_out else ""),
        ]
        if self.errors:
            lines.append("ERROR lines:")
            lines += ["  " + e for e in self.errors]
        for name, text in (("stdout", self.stdout), ("stderr", self.stderr)):
            t = text.rstrip().splitlines()[-tail:]
            if t:
                lines.append("--- last %d lines of %s:" % (len(t), name))
                lines += t
        return "\n".join(lines)

    def __repr__(self):
        return "RunResult(returncode=%r, blocks=%d, errors=%d, workdir=%s)" % (
            self.returncode, len(self.thermo), len(self.errors), self.workdir)


def _grep_lines(word, *texts):
    seen, out = set(), []
    for text in texts:
        for line in (text or "").splitlines():
            s = line.strip()
            if s.startswith(word) and s not in seen:
                seen.add(s)
                out.append(s)
    return out


# ----------------------------------------------------------------------------------- running

def _mpirun():
    exe = os.environ.get("HARDCONTACT_MPIRUN") or shutil.which("mpirun")
    if not exe:
        raise LammpsRunError("mpirun not found (install openmpi-bin, or set HARDCONTACT_MPIRUN)")
    return exe


def _looks_like_deck_text(deck):
    return isinstance(deck, str) and ("\n" in deck or not os.path.isfile(deck))


def run_deck(lmp, deck, np=1, workdir=".", variables=None, expect_error=False,
             timeout=DEFAULT_TIMEOUT, args=(), files=(), deck_name="in.deck", log_name="log.lammps",
             env=None):
    """Run one deck and return a RunResult.

    lmp          the LAMMPS executable (build/lmp_hardcontact), or a Host (test_args().lmp):
                 a Host with a plugin runs the deck with `plugin load <plugin>` prepended,
                 the liggghts Host runs it as liggghts_deck() rewrites it
    deck         the input text, or the path of an input file (run with -in <absolute path>;
                 on a plugin or liggghts host, its rewritten copy runs in workdir)
    np           number of MPI ranks: 1 = plain exec, > 1 = mpirun --oversubscribe -np N
    workdir      directory the deck runs in (created); relative file names in the deck refer to it
    variables    {name: value} -> -var name value (a list/tuple value gives several words)
    expect_error True: the run must fail (non-zero exit); its result is returned for checks
    timeout      seconds of wall time before the whole process group is killed
    args         extra command-line words for LAMMPS (e.g. ["-echo", "screen"])
    files        paths copied into workdir before the run (data files, includes)
    """
    workdir = Path(workdir).resolve()
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / _MARKER).touch()
    for f in files:
        shutil.copy(str(f), str(workdir))
    rewriting_host = getattr(lmp, "rewrites", False)
    if _looks_like_deck_text(deck) or rewriting_host:
        text = deck if _looks_like_deck_text(deck) else Path(deck).read_text()
        if rewriting_host:
            text = lmp.deck_text(text)
            if not _looks_like_deck_text(deck):
                deck_name = Path(deck).name
        deck_path = workdir / deck_name
        deck_path.write_text(text if text.endswith("\n") else text + "\n")
    else:
        deck_path = Path(deck).resolve()
    log_path = workdir / log_name
    if log_path.exists():
        log_path.unlink()

    cmd = [str(Path(lmp).resolve()), "-in", str(deck_path), "-log", log_name]
    for name, value in (variables or {}).items():
        values = value if isinstance(value, (list, tuple)) else [value]
        cmd += ["-var", str(name)] + [str(v) for v in values]
    cmd += [str(a) for a in args]
    if int(np) > 1:
        cmd = [_mpirun(), "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
               "-np", str(int(np))] + cmd

    run_env = dict(os.environ)
    run_env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    run_env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    run_env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")   # ranks > cores: do not spin
    run_env.setdefault("OMP_NUM_THREADS", "1")
    if expect_error and int(np) > 1:
        # Once the first rank exits non-zero, mpirun waits odls_base_sigkill_timeout (1 s)
        # before it kills the others. A run meant to fail needs no grace: 1.46 -> 0.38 s per
        # erroring deck at np 2, the same ERROR lines.
        run_env.setdefault("OMPI_MCA_odls_base_sigkill_timeout", "0")
    if env:
        run_env.update({k: str(v) for k, v in env.items()})

    t0 = time.monotonic()
    timed_out = False
    # errors="replace": LIGGGHTS prints bytes that are not UTF-8 (uninitialised text in a banner)
    with open(workdir / "stdout.txt", "w+", errors="replace") as out, \
            open(workdir / "stderr.txt", "w+", errors="replace") as err:
        proc = subprocess.Popen(cmd, cwd=str(workdir), stdin=subprocess.DEVNULL, stdout=out,
                                stderr=err, env=run_env, start_new_session=True)
        try:
            returncode = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            _kill_group(proc)
            returncode = None
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read(), err.read()
    seconds = time.monotonic() - t0
    log = log_path.read_text(errors="replace") if log_path.exists() else ""

    res = RunResult(cmd, workdir, returncode, stdout, stderr, log, seconds, timed_out)
    if timed_out:
        raise LammpsRunError("LAMMPS run timed out after %.0f s\n%s" % (timeout, res.summary()))
    if expect_error and returncode == 0:
        raise LammpsRunError("LAMMPS run was expected to fail but exited 0\n" + res.summary())
    if not expect_error and returncode != 0:
        raise LammpsRunError("LAMMPS run failed\n" + res.summary())
    return res


def _kill_group(proc):
    for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            pass


# ----------------------------------------------------------------------------------- thermo

def _is_number(tok):
    try:
        float(tok)
        return True
    except ValueError:
        return False


def _columns_to_arrays(names, rows):
    out = {}
    for j, name in enumerate(names):
        col = [r[j] for r in rows]
        if all(_is_int_token(t) for t in col):
            out[name] = np.array([int(t) for t in col], dtype=np.int64)
        else:
            out[name] = np.array([float(t) for t in col], dtype=np.float64)
    return out


def _is_int_token(tok):
    t = tok[1:] if tok[:1] in "+-" else tok
    return t.isdigit()


def parse_thermo(text):
    """Thermo blocks of a LAMMPS log (or screen output): a list with one dict per run, column
    name -> numpy array. A block starts at the header line printed after 'Per MPI rank memory
    allocation' (thermo_style one/custom; 'Memory usage per processor' in LIGGGHTS) and ends at
    'Loop time' (or at an ERROR / the end of the text for a run that died). Lines inside a block
    that are not a full row of numbers (warnings, fix output) are skipped. LIGGGHTS heads its
    columns without the f_/c_/v_ prefixes ("hc[7]" for f_hc[7]): those are named after the
    words of the last echoed `thermo_style custom` line instead, so tests read the same names on
    every host."""
    blocks = []
    lines = text.splitlines()
    i, n = 0, len(lines)
    custom = None
    while i < n:
        words = lines[i].split()
        if len(words) > 2 and words[0] == "thermo_style" and words[1] == "custom":
            custom = [w for w in words[2:] if not w.startswith("#")]
        if not (lines[i].startswith("Per MPI rank memory allocation") or
                lines[i].startswith("Memory usage per processor")):
            i += 1
            continue
        i += 1
        while i < n and not lines[i].strip():
            i += 1
        if i >= n:
            break
        names = lines[i].split()
        if not names or any(_is_number(t) for t in names):
            continue
        if custom and len(custom) == len(names):
            names = [c if c.endswith("_" + m) else m for c, m in zip(custom, names)]
        rows = []
        i += 1
        while i < n:
            line = lines[i]
            if line.startswith("Loop time") or line.startswith("ERROR") or \
                    line.startswith("Per MPI rank memory allocation") or \
                    line.startswith("Memory usage per processor"):
                break
            toks = line.split()
            if len(toks) == len(names) and all(_is_number(t) for t in toks):
                rows.append(toks)
            i += 1
        blocks.append(_columns_to_arrays(names, rows))
    return blocks


# ----------------------------------------------------------------------------------- dumps

# (timestep, {column: numpy array}, box bounds: array (3,2) or (3,3) for triclinic)
DumpFrame = namedtuple("DumpFrame", ["timestep", "columns", "box"])


def _open_text(path):
    path = str(path)
    if path.endswith(".gz"):
        return gzip.open(path, "rt")
    return open(path, "r")


def _convert_column(tokens):
    try:
        if all(_is_int_token(t) for t in tokens):
            return np.array(tokens, dtype=np.int64)
        return np.array(tokens, dtype=np.float64)
    except ValueError:
        return np.array(tokens, dtype=object)    # e.g. element names


def _read_frames(path, item):
    """Generic reader of LAMMPS text dumps whose per-frame table is 'ITEM: <item> cols...'."""
    paths = sorted(glob.glob(str(path))) if any(c in str(path) for c in "*?[") else [path]
    if not paths:
        raise FileNotFoundError(path)
    frames = []
    for p in paths:
        with _open_text(p) as f:
            lines = f.read().splitlines()
        i, n = 0, len(lines)
        while i < n:
            if not lines[i].startswith("ITEM: TIMESTEP"):
                i += 1
                continue
            timestep = int(lines[i + 1].split()[0])
            i += 2
            count, box, names = None, None, None
            while i < n:
                line = lines[i]
                if line.startswith("ITEM: NUMBER OF"):
                    count = int(lines[i + 1].split()[0])
                    i += 2
                elif line.startswith("ITEM: BOX BOUNDS"):
                    box = np.array([[float(x) for x in lines[i + k].split()] for k in (1, 2, 3)])
                    i += 4
                elif line.startswith("ITEM: " + item):
                    names = line.split()[2:]
                    i += 1
                    break
                elif line.startswith("ITEM: TIMESTEP"):
                    raise ValueError("%s: frame at step %d has no 'ITEM: %s' table" % (p, timestep, item))
                else:
                    i += 1
            if names is None or count is None:
                raise ValueError("%s: truncated frame at step %d" % (p, timestep))
            rows = lines[i:i + count]
            if len(rows) < count:
                raise ValueError("%s: frame at step %d has %d of %d rows" % (p, timestep, len(rows), count))
            i += count
            toks = [r.split() for r in rows]
            cols = {}
            for j, name in enumerate(names):
                cols[name] = _convert_column([t[j] for t in toks])
            frames.append(DumpFrame(timestep, cols, box))
    frames.sort(key=lambda fr: fr.timestep)
    return frames


def read_dump(path, sort_by_id=True):
    """Frames of a text 'dump custom' (or atom) file: a list of DumpFrame(timestep,
    {column: numpy array}, box), box as an array [[xlo, xhi(, xy)], [ylo, yhi(, xz)],
    [zlo, zhi(, yz)]]. Rows are sorted by the 'id' column when there is one (the order in the
    file depends on the processors). path may be gzipped (.gz) or a glob pattern (one file per
    step, 'dump.*.txt')."""
    frames = _read_frames(path, "ATOMS")
    if sort_by_id:
        for fr in frames:
            if "id" in fr.columns and len(fr.columns["id"]):
                order = np.argsort(fr.columns["id"], kind="stable")
                for k in fr.columns:
                    fr.columns[k] = fr.columns[k][order]
    return frames


def read_dump_local(path):
    """Frames of a text 'dump local' file: same shape as read_dump, with the columns of
    'ITEM: ENTRIES ...' (in file order)."""
    return _read_frames(path, "ENTRIES")


# ----------------------------------------------------------------------------------- scripts

def test_args(description=None, argv=None):
    """Command line of a deck test, as registered by hardcontact_deck_test() in
    tests/CMakeLists.txt: --lmp <exe> --np <N> --workdir <dir> (plus --timeout, and --host
    modern --plugin <so> for a modern LAMMPS that loads the fix as a plugin). args.lmp is a
    Host: pass it to run_deck as it is."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--lmp", default=None,
                   help="LAMMPS executable: with fix hardcontact (launcher host, default "
                        "build/lmp_hardcontact) or with the PLUGIN package (modern host)")
    p.add_argument("--host", choices=("launcher", "modern", "liggghts"), default="launcher",
                   help="launcher: the fix is built in; modern: every deck starts with "
                        "'plugin load <--plugin>'; liggghts: LIGGGHTS with the fix built in "
                        "(--lmp build/liggghts_hardcontact), decks rewritten where it differs")
    p.add_argument("--plugin", default=None,
                   help="hardcontactplugin.so built against the modern LAMMPS (--host modern)")
    p.add_argument("--np", type=int, default=1, help="MPI ranks (default 1: no mpirun)")
    p.add_argument("--workdir", default=None,
                   help="where the decks run (default: build/tests/work/<script name>)")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT, help="seconds per LAMMPS run")
    a = p.parse_args(argv)
    if a.host == "modern":
        if not a.lmp or not a.plugin:
            p.error("--host modern needs --lmp <modern lmp> and --plugin <hardcontactplugin.so>")
        a.lmp = Host(a.lmp, "modern", a.plugin)
    elif a.host == "liggghts":
        a.lmp = Host(a.lmp or _REPO / "build" / "liggghts_hardcontact", "liggghts")
    else:
        a.lmp = Host(a.lmp or _REPO / "build" / "lmp_hardcontact", "launcher")
    if a.workdir is None:
        a.workdir = str(_REPO / "build" / "tests" / "work" / Path(sys.argv[0]).stem)
    fresh_workdir(a.workdir)
    return a


def fresh_workdir(path):
    """Empty a work directory from an earlier run (only one that run_deck created, or an empty
    one) and create it."""
    path = Path(path)
    if path.exists():
        if (path / _MARKER).exists():
            shutil.rmtree(str(path))
        elif any(path.iterdir()):
            raise LammpsRunError("refusing to clear %s: not a lammps_run work directory" % path)
    path.mkdir(parents=True, exist_ok=True)
    (path / _MARKER).touch()
    return path


def check(condition, message):
    """assert that survives python -O; message says what should hold."""
    if not condition:
        raise AssertionError(message)
    print("ok:", message)


def main(test):
    """Run test() and turn the outcome into an exit status with a short report."""
    try:
        test()
    except (AssertionError, LammpsRunError) as e:
        print("FAIL: %s" % e, file=sys.stderr)
        sys.exit(1)
    print("PASS")
