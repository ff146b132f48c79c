#!/usr/bin/python3
"""Where the total energy of a staggered electric run goes, step by step.

Reads the time-series.csv of willmore-flow runs with a field and prints, per
run, how the change of the total energy over the steps splits into the step
with psi frozen (column frozen_step_energy_change: what the step minimises,
never positive but for the work of the constraint multipliers) and the
update of psi that follows (potential_update_energy_change), and how much of
that update is the electrolyte term (E8): with e_in = e_out its phi-derivative
vanishes, so the frozen step leaves it unchanged and its whole change over a
step comes from the update of psi. Issue 16, item 3; doc/validation.md.

usage: tools/energy-split.py LABEL=DIR [LABEL=DIR ...]
"""
import csv
import sys


def summary(directory):
    with open(directory + "/time-series.csv") as f:
        rows = list(csv.DictReader(f))
    frozen = [float(r["frozen_step_energy_change"]) for r in rows]
    update = [float(r["potential_update_energy_change"]) for r in rows]
    total = [a + b for a, b in zip(frozen, update)]
    rises = [t for t in total if t > 0]
    electrolyte = [float(r["electrolyte_dielectric_energy"]) for r in rows]
    electrolyte_change = [b - a for a, b in zip(electrolyte, electrolyte[1:])]
    return {
        "steps": len(rows),
        "t_end": float(rows[-1]["t"]),
        "bending": (float(rows[0]["bending_energy"]),
                    float(rows[-1]["bending_energy"])),
        "frozen_sum": sum(frozen),
        "frozen_max": max(frozen),
        "update_sum": sum(update),
        "update_up": sum(u for u in update if u > 0),
        "update_down": sum(u for u in update if u < 0),
        "rising_steps": len(rises),
        "largest_rise": max(rises) if rises else 0.0,
        "rise_sum": sum(rises),
        "electrolyte_sum": sum(electrolyte_change),
        "electrolyte_abs": sum(abs(d) for d in electrolyte_change),
        "update_abs": sum(abs(u) for u in update[1:]),
    }


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print("| run | steps | t end | E_B start, end | sum frozen steps | "
          "largest frozen step | sum psi updates (up, down) | steps where "
          "the total rose | largest rise | sum of rises | sum of abs(psi updates) "
          "(steps 2 on) | of it (E8) |")
    print("| --- " * 12 + "|")
    for arg in sys.argv[1:]:
        label, directory = arg.split("=", 1)
        s = summary(directory)
        print(f"| {label} | {s['steps']} | {s['t_end']:.4g} | "
              f"{s['bending'][0]:.4g}, {s['bending'][1]:.4g} | "
              f"{s['frozen_sum']:.4g} | {s['frozen_max']:.2g} | "
              f"{s['update_sum']:.4g} ({s['update_up']:.4g}, "
              f"{s['update_down']:.4g}) | {s['rising_steps']} | "
              f"{s['largest_rise']:.3g} | {s['rise_sum']:.4g} | "
              f"{s['update_abs']:.4g} | {s['electrolyte_abs']:.4g} |")


if __name__ == "__main__":
    main()
