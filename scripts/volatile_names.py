"""The names of values that measure the machine, not the model: wall times, rates, thread counts
and their reasons, memory, load. scripts/compare-results and scripts/check-slurm leave them out
when they compare two runs of the pipeline. run_s: the EFG slab's cost.run_s, the wall time of its
time loop; convolution_s: a superposed run's convolutions; 'per second': mw-fem's metric 'steps per
second'; pareto: speed.csv's flag of the runs no other beats in both wall time and error, so it
follows the wall times."""
import re

VOLATILE = re.compile(r'(wall|setup_s|run_s$|convolution_s$|per_s\b|per second|ns_per|thread|rss|memory|cpu_s|load|pareto)', re.I)
