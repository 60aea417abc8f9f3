#!/usr/bin/env python3
"""Exact (event-driven) sticky-particle motion on a line, for comparison with the scheme.

Particles of radius r (equal masses here, any masses allowed) move freely; when two clusters
touch (gap between neighbouring particles = 2 r) they merge into one cluster that moves with
their common momentum (perfectly inelastic, restitution 0). Clusters never split. Every event
is found exactly (free flight between events), so the result is exact up to round-off.

    import sticky_exact as se
    clusters, t_last = se.solve(q0, u0, r, m)          # all merges, time of the last one
    x, v = se.state(q0, u0, r, m, t)                   # positions and velocities at time t
"""


class _Cluster:
    def __init__(self, first, last, mass, mom, left0, t0):
        self.first, self.last = first, last        # particle indices (inclusive)
        self.mass, self.mom = mass, mom
        self.left0, self.t0 = left0, t0            # left particle's centre at time t0

    @property
    def v(self):
        return self.mom / self.mass

    def left(self, t):
        return self.left0 + self.v * (t - self.t0)

    def right(self, t, r):
        return self.left(t) + 2.0 * r * (self.last - self.first)


def _run(q0, u0, r, m, t_end=float("inf")):
    n = len(q0)
    cl = [_Cluster(i, i, m[i], m[i] * u0[i], q0[i], 0.0) for i in range(n)]
    t, events = 0.0, []
    while True:
        best, k_best = None, None
        for k in range(len(cl) - 1):
            a, b = cl[k], cl[k + 1]
            dv = a.v - b.v
            if dv <= 0.0:
                continue
            gap = b.left(t) - a.right(t, r) - 2.0 * r
            dt = max(gap, 0.0) / dv
            if best is None or dt < best:
                best, k_best = dt, k
        if best is None or t + best > t_end:
            return cl, t, events
        t += best
        a, b = cl[k_best], cl[k_best + 1]
        merged = _Cluster(a.first, b.last, a.mass + b.mass, a.mom + b.mom, a.left(t), t)
        cl[k_best:k_best + 2] = [merged]
        events.append(t)


def solve(q0, u0, r, m=None):
    """All merges: the final clusters (list of (first, last, mass, velocity)) and the time of the
    last merge."""
    m = m or [1.0] * len(q0)
    cl, t, events = _run(q0, u0, r, m)
    return [(c.first, c.last, c.mass, c.v) for c in cl], (events[-1] if events else 0.0)


def state(q0, u0, r, m=None, t=0.0):
    """Positions and velocities of every particle at time t."""
    m = m or [1.0] * len(q0)
    cl, _, _ = _run(q0, u0, r, m, t)
    x, v = [0.0] * len(q0), [0.0] * len(q0)
    for c in cl:
        for i in range(c.first, c.last + 1):
            x[i] = c.left(t) + 2.0 * r * (i - c.first)
            v[i] = c.v
    return x, v


def pathlines(q0, u0, r, m=None, times=()):
    return [state(q0, u0, r, m, t)[0] for t in times]


if __name__ == "__main__":
    import make_data
    q, u, r = make_data.particles()
    clusters, t_last = solve(q, u, r)
    print("last merge at t = %.6f; %d final clusters:" % (t_last, len(clusters)))
    for c in clusters:
        print("  particles %2d-%2d  mass %g  velocity %+.12f" % (c[0] + 1, c[1] + 1, c[2], c[3]))
