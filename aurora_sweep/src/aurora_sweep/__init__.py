"""The sweep's Python side: aurora_sweep.plot_sweep, the plots of a sweep's
results, run by the sweep program at the end (`rosrun aurora_sweep plot_sweep
DIR`) and by `aurora.sweep`'s users (`from aurora_sweep.plot_sweep import
main`). It reads the results and summary.json only (no import of `aurora`):
the sweep program sits below the Python package `aurora`, which runs it."""
