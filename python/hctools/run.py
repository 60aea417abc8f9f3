"""Running a deck on any host and rank count: Debian's LAMMPS with the fix built in (the
launcher), a modern LAMMPS that loads the plugin, or LIGGGHTS 3.8, serially or under mpirun.

    from hctools import Host, run_deck
    res = run_deck("build/lmp_hardcontact", DECK, np=2, workdir="out/run1")
    res.thermo[-1]["Step"], res.seconds, res.log

A failed run (non-zero exit, timeout) raises LammpsRunError with the ERROR lines and the tail
of the output, unless expect_error=True, which instead requires a failure.
"""

import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

from .logs import parse_thermo

DEFAULT_TIMEOUT = 600.0
# a folder run_deck made: fresh_workdir (tests) may clear it
WORKDIR_MARKER = ".lammps_run_workdir"


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
    out = ["newton          off    # added for LIGGGHTS (hctools.run.liggghts_deck)"]
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

    lmp          the LAMMPS executable (build/lmp_hardcontact), or a Host (the tests' test_args().lmp):
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
    (workdir / WORKDIR_MARKER).touch()
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
    session_dir = None
    if int(np) == 1 and "OMPI_MCA_ess_singleton_isolated" not in run_env:
        # A serial run is an MPI singleton: by default Open MPI starts an orted daemon for it,
        # 0.17 s of each run's 0.46 s start-up (a trivial deck, every host); isolated, the run
        # does not spawn one (it needs none: no MPI_Comm_spawn). Isolated singletons all take
        # job family 0, so they would share one session directory, and one ending removed it
        # under another one starting (orte_session_dir failed, once in a CI run): each run
        # gets its own.
        session_dir = tempfile.mkdtemp(prefix="hc-ompi-")
        run_env["OMPI_MCA_ess_singleton_isolated"] = "1"
        run_env["OMPI_MCA_orte_tmpdir_base"] = session_dir
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
    if session_dir is not None:
        shutil.rmtree(session_dir, ignore_errors=True)
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
