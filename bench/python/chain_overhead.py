#!/usr/bin/python3
"""The whole chain on the demo corpus from Python against the same chain in C++ (issue 27:
"costs less than 5 % more"). Not a test: a measurement, recorded in docs/PERFORMANCE.md.

C++: bench_pipeline's BM_WholeChain/with_arma:1 (runChain on the demo corpus, every stage, one
thread). Python: bunraku.analyse(demo corpus, threads=1), the same runChain behind the
binding's costs (the corpus copied and keyed, the GIL released around a worker thread, the
results wrapped). The two alternate in rounds so that a change in the machine's load falls on
both; each round reports medians.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/chain_overhead.py build/bin/bench_pipeline [rounds]
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import time

import bunraku


def python_chain_ms(corpus: bunraku.Corpus, runs: int) -> tuple[float, float, float]:
    wall, cpu = [], []
    for _ in range(runs):
        w0, c0 = time.perf_counter(), time.process_time()
        analysis = bunraku.analyse(corpus, threads=1)
        cpu.append((time.process_time() - c0) * 1e3)
        wall.append((time.perf_counter() - w0) * 1e3)
        del analysis
    return statistics.median(wall), statistics.median(cpu), min(cpu)


def cpp_chain_ms(bench: str, runs: int) -> tuple[float, float, float]:
    result = subprocess.run([bench, "--benchmark_filter=BM_WholeChain/with_arma:1$", f"--benchmark_repetitions={runs}",
                             "--benchmark_min_time=0.01", "--benchmark_format=json"], capture_output=True, text=True, check=True)
    runs_ = [b for b in json.loads(result.stdout)["benchmarks"] if b.get("run_type") == "iteration"]
    return (statistics.median(b["real_time"] for b in runs_), statistics.median(b["cpu_time"] for b in runs_),
            min(b["cpu_time"] for b in runs_))


def main() -> None:
    bench = sys.argv[1] if len(sys.argv) > 1 else "build/bin/bench_pipeline"
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    corpus = bunraku.Corpus.open("demo")
    bunraku.analyse(corpus, threads=1)  # warm: the module, FFTW plans, the caches
    print(f"load average {os.getloadavg()[0]:.1f}; {rounds} rounds of 9 runs each")
    print("round  C++ wall  C++ CPU (min)   Python wall  Python CPU (min)   overhead: median CPU, min CPU")
    ratios, best_cpp, best_py = [], [], []
    for r in range(rounds):
        cpp_wall, cpp_cpu, cpp_min = cpp_chain_ms(bench, 9)
        py_wall, py_cpu, py_min = python_chain_ms(corpus, 9)
        ratios.append(py_cpu / cpp_cpu - 1.0)
        best_cpp.append(cpp_min)
        best_py.append(py_min)
        print(f"{r + 1:5d}  {cpp_wall:8.1f}  {cpp_cpu:7.1f} ({cpp_min:5.1f})   {py_wall:11.1f}  {py_cpu:10.1f} ({py_min:5.1f})"
              f"   {100 * ratios[-1]:+6.1f} %, {100 * (py_min / cpp_min - 1.0):+6.1f} %")
    print(f"median of the rounds' overheads (median CPU): {100 * statistics.median(ratios):+.1f} %")
    print(f"overhead of the fastest runs (min CPU over all rounds): {100 * (min(best_py) / min(best_cpp) - 1.0):+.1f} %"
          f" ({min(best_py):.1f} ms vs {min(best_cpp):.1f} ms)")


if __name__ == "__main__":
    main()
