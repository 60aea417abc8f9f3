"""Pieces of LAMMPS decks that the project's decks share."""


def preamble(boundary="f f f", dimension=3, ghost_velocities=False, units="lj"):
    """The first lines of a deck of finite-size spheres: units, atom_style sphere, the
    dimension and boundary, an atom map (the fix looks atoms up by id), and with
    ghost_velocities `comm_modify vel yes` (friction and moving walls read the velocities of
    ghost atoms; the fix sends the ones its solve needs itself, so this is for other readers).
    Ends with a newline; holds no braces, so a str.format template may follow it."""
    lines = [
        "units           %s" % units,
        "atom_style      sphere",
        "dimension       %d" % dimension,
        "boundary        %s" % boundary,
        "atom_modify     map array",
    ]
    if ghost_velocities:
        lines.append("comm_modify     vel yes")
    return "\n".join(lines) + "\n"
