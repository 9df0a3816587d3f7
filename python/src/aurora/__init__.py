"""AuRoRA-ROS from Python.

Modules:
    aurora.report      the analysis of a recorded flight (bag -> metrics, figures,
                       video, report.md); `rosrun aurora report` calls it
    aurora.formation_report  its part for a formation's bag (formation.launch)

    aurora.simulate    one offline flight on the C++ core (aurora.simulation)
    aurora.simulate_formation  one offline formation flight (flight --formation's)
    aurora.sweep       a sweep on the sweep program's backends -> (DataFrame, summary) (aurora.sweep_runner)
    aurora.read_results, aurora.read_summary  a sweep folder's results and summary.json
    aurora.read_bag, aurora.read_formation_bag  a recorded flight as DataFrames (aurora.bags)
    aurora.identify    a recorded loop's delays, link and vehicle model (identify.json as a dict;
                       `rosrun aurora identify` writes its files; aurora/identification.py, identify_core.py)

See docs/architecture.md, "Packages and data flow".
"""
from aurora.simulation import Flight, FormationFlight, ShapedFormationFlight, simulate, simulate_formation  # noqa: F401
from aurora.sweep_runner import SweepInterrupted, read_results, read_summary, sweep, sweep_program  # noqa: F401,E402
from aurora.bags import BagFlight, read_bag, read_formation_bag  # noqa: F401,E402
from aurora.identification import identify  # noqa: F401,E402
from aurora import widgets_compat  # noqa: E402

widgets_compat.apply()  # sliders execute under plain `jupyter nbconvert --execute` (aurora/widgets_compat.py)

__all__ = ["Flight", "FormationFlight", "ShapedFormationFlight", "simulate", "simulate_formation", "SweepInterrupted", "read_results",
           "read_summary", "sweep", "sweep_program", "BagFlight", "read_bag", "read_formation_bag", "identify"]
