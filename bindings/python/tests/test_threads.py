"""Long calls release the GIL (a second Python thread progresses while a normalisation runs)
and stop on Ctrl-C (KeyboardInterrupt through the analysis's stop token)."""

from __future__ import annotations

import _thread
import threading
import time

import pytest

import bunraku

# A slower normalisation of the demo corpus (about a second on one thread): a wide search band,
# a long window and 81 scales.
SLOW = dict(searchBand=100, tau=20, scales=[1 + 0.25 * k for k in range(81)], threads=1)


@pytest.fixture(scope="module")
def preprocessed():
    return bunraku.preprocess(bunraku.Corpus.open("demo"))


def test_a_second_thread_progresses_during_a_normalisation(preprocessed):
    counts = []
    stop = threading.Event()

    def count():
        n = 0
        while not stop.is_set():
            n += 1  # pure Python: runs only while it holds the GIL
            if n % 1000 == 0:
                counts.append((time.perf_counter(), n))

    worker = threading.Thread(target=count)
    worker.start()
    try:
        time.sleep(0.05)
        started = time.perf_counter()
        bunraku.normalise(preprocessed, **SLOW)
        finished = time.perf_counter()
    finally:
        stop.set()
        worker.join()
    during = [n for t, n in counts if started <= t <= finished]
    # the counter advanced by many steps while the C++ ran: the GIL was released
    assert len(during) >= 10, f"{len(during)} counter ticks during {finished - started:.3f} s"


def test_ctrl_c_interrupts_a_long_normalisation(preprocessed):
    started = time.perf_counter()
    bunraku.normalise(preprocessed, **SLOW)
    full = time.perf_counter() - started

    timer = threading.Timer(0.1, _thread.interrupt_main)  # as Ctrl-C: SIGINT's handler on the main thread
    started = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        bunraku.normalise(preprocessed, **SLOW)
    interrupted = time.perf_counter() - started
    timer.join()
    # stopped at the matcher's next check, long before the whole normalisation
    assert interrupted < 0.1 + 0.4 * full, f"interrupted after {interrupted:.3f} s of {full:.3f} s"
    # the module still works after an interruption
    assert len(bunraku.normalise(preprocessed, threads=1).cells) == 6
