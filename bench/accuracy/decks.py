"""LAMMPS input decks of the benchmark (hardcontact and the soft-sphere twin)."""

HEAD_DATA = """units           si
dimension       {dim}
atom_style      sphere
boundary        f f {zb}
atom_modify     map array
read_data       {data}
"""


def dim_of(scene):
    return scene.get("dim", 2)


def dimension(scene):
    """The deck's dimension and z boundary: 2d scenes are periodic in z (LAMMPS needs it for
    dimension 2), pile3d has walls there."""
    d = dim_of(scene)
    return dict(dim=d, zb="p" if d == 2 else "f")


def head_data(scene, data):
    """The start of a deck that reads a data file."""
    return HEAD_DATA.format(data=data, **dimension(scene))

HEAD_RESTART = """units           si
read_restart    {restart}
"""

HARD_FIXES = """pair_style      none
neighbor        {skin!r} bin
neigh_modify    delay 0 every 1 check {check}
{gravity}fix             hc all hardcontact {walls} solver {solver} tol {tol!r} warmstart {warm} maxiter {maxiter}
{e2d}timestep        {h!r}
"""
E2D = "fix             e2d all enforce2d\n"


def hard_fixes(scene, **kw):
    return HARD_FIXES.format(e2d=E2D if dim_of(scene) == 2 else "", **kw)

DIAG = """compute         ke all ke
variable        sp atom sqrt(vx*vx+vy*vy+vz*vz)
compute         vmax all reduce max v_sp
thermo_style    custom step time c_ke c_vmax f_hc[1] f_hc[2] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7] f_hc[9]
thermo_modify   norm no format float %.12g
"""


def gravity_line(g):
    return "fix             grav all gravity %r vector 0 -1 0\n" % g if g else ""


def hard(scene, start, solver, tol, warm, lead, window, cap, maxiter=10000, check="yes",
         h=None, skin=None, gapdump_every=0, write_restart_at=None, write_data_at=None,
         final_restart=None, lead_cap=None):
    """A hardcontact run: lead-in (not measured), then the measured window (thermo every
    step), both stopped by fix halt after `cap` seconds. start: ('data', file) or
    ('restart', file)."""
    kind, f = start
    text = (head_data(scene, f) if kind == "data" else HEAD_RESTART.format(restart=f))
    text += hard_fixes(scene, skin=skin or scene["skin"], check=check,
                              gravity=gravity_line(scene["gravity"]), walls=scene["walls"],
                              solver=solver, tol=tol, warm=warm, maxiter=maxiter,
                              h=h or scene["h"])
    text += DIAG
    halt = "fix             halt all halt 1 tlimit > %r error soft message no\n"
    if lead:
        text += halt % float(lead_cap or cap)
        # a soft halt leaves the timer expired, which would skip every later run
        text += "thermo          %d\nrun             %d\nunfix           halt\ntimer           timeout off\n" % (lead, lead)
    text += halt % float(cap)
    if gapdump_every:
        text += ("dump            ga all custom %d gap.dump id radius x y z vx vy vz\n"
                 "dump_modify     ga sort id format float %%.17g\n"
                 "dump            gl all local %d gap.local f_hc[1] f_hc[2] f_hc[3] f_hc[7]\n"
                 "dump_modify     gl format float %%.17g\n" % (gapdump_every, gapdump_every))
    text += "thermo          1\n"
    if write_restart_at:
        # a reference run that leaves the probe state (restart with warm-start multipliers)
        text += "run             %d\n" % write_restart_at
        text += "write_restart   probe.restart\n"
        if write_data_at:
            text += "write_data      probe.data nocoeff\n"
        rest = window - write_restart_at
        if rest > 0:
            text += "run             %d\n" % rest
    else:
        text += "run             %d\n" % window
    if final_restart:
        text += "write_restart   %s\nwrite_data      %s nocoeff\n" % final_restart
        text += "write_dump      all local final.local f_hc[1] f_hc[2] f_hc[3] f_hc[7] modify format float %.17g\n"
    return text


def probe(scene, restart, solver, tol, warm, maxiter=10000, check="yes"):
    """One step from the probe state; velocities dumped before and after."""
    text = HEAD_RESTART.format(restart=restart)
    text += hard_fixes(scene, skin=scene["skin"], check=check, gravity=gravity_line(scene["gravity"]),
                              walls=scene["walls"], solver=solver, tol=tol, warm=warm,
                              maxiter=maxiter, h=scene["h"])
    text += DIAG
    text += ("dump            pv all custom 1 probe.dump id vx vy vz\n"
             "dump_modify     pv sort id format float %.17g\n"
             "thermo          1\nrun             1\n")
    return text


def settle(scene, data, n_fall, h_fall, skin_fall, tol_fall, n_relax, tol_relax, visc,
           n_hold, tol_hold):
    """Piles: fall with small steps (list rebuilt every step), relax with the benchmark's step
    under a viscous drag (an external force like gravity: frictionless grains creep for a long
    time otherwise), then hold without drag at tol_hold; writes start.restart / start.data /
    start.local."""
    text = head_data(scene, data)
    grav = gravity_line(scene["gravity"])
    defined = False

    def phase(skin, tol, h, n, every):
        nonlocal defined
        t = ""
        if defined:
            t += "unfix           hc\n" + ("unfix           e2d\n" if dim_of(scene) == 2 else "")
            t += "unfix           grav\n" if grav else ""
        t += hard_fixes(scene, skin=skin, check="yes", gravity=grav, walls=scene["walls"],
                               solver="apgd", tol=tol, warm="yes", maxiter=10000, h=h)
        if not defined:
            t += DIAG
        defined = True
        return t + "thermo          %d\nrun             %d\n" % (every, n)

    if n_fall:
        text += phase(skin_fall, tol_fall, h_fall, n_fall, max(n_fall // 10, 1))
    if n_relax:
        text += "fix             visc all viscous %r\n" % visc
        text += phase(scene["skin"], tol_relax, scene["h"], n_relax, max(n_relax // 10, 1))
        text += "unfix           visc\n"
    text += phase(scene["skin"], tol_hold, scene["h"], n_hold, 1)
    text += "write_restart   start.restart\nwrite_data      start.data nocoeff\n"
    text += "write_dump      all local start.local f_hc[1] f_hc[2] f_hc[3] f_hc[7] modify format float %.17g\n"
    return text


SOFT = """units           si
dimension       {dim}
atom_style      sphere
boundary        f f {zb}
atom_modify     map array
comm_modify     vel yes
read_data       {data}
velocity        all set 0.0 0.0 0.0 {zero}
pair_style      gran/hertz/history {kn!r} NULL {gn!r} NULL 0.0 1
pair_coeff      * *
neighbor        {skin!r} bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity {g!r} vector 0 -1 0
fix             nve all nve/sphere
fix             wx all wall/gran hertz/history {kn!r} NULL {gn!r} NULL 0.0 1 xplane 0.0 {width!r}
fix             wy all wall/gran hertz/history {kn!r} NULL {gn!r} NULL 0.0 1 yplane 0.0 NULL
{third}timestep        {dt!r}
compute         pl all pair/local force dist cutoff radius
compute         pp all property/local patom1 patom2 cutoff radius
compute         red all reduce max c_pl[1] c_pl[2] c_pp[1] c_pp[2] replace 2 1 replace 3 1 replace 4 1
compute         rad all property/atom radius
variable        wb atom (y-c_rad)/c_rad
variable        wl atom (x-c_rad)/c_rad
variable        wr atom ({width!r}-x-c_rad)/c_rad
{zgaps}compute         wmin all reduce min v_wb v_wl v_wr{zmin}
thermo_style    custom step time c_red[1] c_wmin[1]
thermo_modify   norm no
fix             halt all halt 100 tlimit > {cap!r} error soft message no
"""


def soft(scene, data, kn, gn, dt, n_settle, viscous, n_window, track_every, dump_every, cap,
         zero_velocity=True):
    """Soft-sphere twin (gran/hertz/history, frictionless: xmu = 0): optional settling with
    fix viscous, then the measured window. Overlap tracking: every track_every steps, the pair
    carrying the largest force (ids and distance) and the smallest wall gaps (track.txt); every
    dump_every steps all positions (soft.dump)."""
    width = scene["box"][0][1]
    if dim_of(scene) == 2:
        third, zgaps, zmin = E2D, "", ""
    else:    # the walls in z, and their gaps (the box is width_d square)
        depth = scene["box"][2][1]
        third = ("fix             wz all wall/gran hertz/history %r NULL %r NULL 0.0 1 zplane 0.0 %r\n"
                 % (kn, gn, depth))
        zgaps = ("variable        wf atom (z-c_rad)/c_rad\n"
                 "variable        wk atom (%r-z-c_rad)/c_rad\n" % depth)
        zmin = " v_wf v_wk"
    text = SOFT.format(data=data, zero="" if zero_velocity else "", kn=kn, gn=gn,
                       skin=0.2 * scene["diameter"].mean(), g=scene["gravity"],
                       width=width, dt=dt, cap=float(cap), third=third, zgaps=zgaps, zmin=zmin,
                       **dimension(scene))
    nwall = 3 if dim_of(scene) == 2 else 5
    if not zero_velocity:
        text = text.replace("velocity        all set 0.0 0.0 0.0 \n", "")
    if n_settle:
        text += "fix             visc all viscous %r\nthermo          %d\nrun             %d\nunfix           visc\n" % (
            viscous, max(n_settle // 4, 1), n_settle)
    text += ("fix             trk all ave/time 1 1 %d c_red[1] c_red[2] c_red[3] c_red[4] "
             "%s file track.txt format \" %%.12g\"\n" % (
                 track_every, " ".join("c_wmin[%d]" % (k + 1) for k in range(nwall))))
    text += ("dump            sd all custom %d soft.dump id radius x y z\n"
             "dump_modify     sd sort id format float %%.17g\n" % dump_every)
    text += "thermo          %d\nrun             %d\n" % (max(n_window // 10, 1), n_window)
    return text


def slide(scene, solver="apgd", tol=1e-10, nsteps=200):
    """Disc 2 orbits the fixed disc 1 under a central pull; the gap of the contact after every
    step is printed (thermo)."""
    a = scene["accel"]
    text = head_data(scene, "slide.data")
    text += """group           mover id 2
pair_style      none
neighbor        %r bin
neigh_modify    delay 0 every 1 check no
variable        dx equal x[2]-x[1]
variable        dy equal y[2]-y[1]
variable        dist equal sqrt(v_dx*v_dx+v_dy*v_dy)
variable        gap equal v_dist-%r
variable        vt equal abs(vx[2]*v_dy-vy[2]*v_dx)/v_dist
variable        vn equal (vx[2]*v_dx+vy[2]*v_dy)/v_dist
variable        m2 equal mass[2]
variable        fx equal -v_m2*%r*v_dx/v_dist
variable        fy equal -v_m2*%r*v_dy/v_dist
fix             pull mover addforce v_fx v_fy 0.0
fix             hc mover hardcontact solver %s tol %r
fix             e2d all enforce2d
timestep        %r
thermo_style    custom step v_gap v_vt v_vn f_hc[4] f_hc[1]
thermo_modify   norm no format float %%.15g
thermo          1
run             %d
""" % (scene["skin"], float(scene["diameter"][0]), a, a, solver, tol, scene["h"], nsteps)
    return text
