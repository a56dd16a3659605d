"""The tracer beside Python: the GIL released while it runs, Ctrl+C, the
progress callback in the caller's thread, and no memory kept between renders."""

import os
import signal
import threading
import time

import pytest

import whitted


@pytest.fixture(scope="module")
def big_scene():
    # A render of a few tenths of a second on these machines.
    scene = whitted.field(2000, seed=5)
    scene.render.width, scene.render.height = 320, 240
    return scene


def test_python_runs_while_the_tracer_does(big_scene):
    done = threading.Event()
    seconds = {}

    def render():
        start = time.perf_counter()
        whitted.render(big_scene, spp=64, threads=1)
        seconds["render"] = time.perf_counter() - start
        done.set()

    worker = threading.Thread(target=render)
    counted = 0
    worker.start()
    while not done.is_set():
        counted += 1
        time.sleep(0.001)
    worker.join()
    # With the GIL held the loop would have stood still for the whole render.
    assert seconds["render"] > 0.1
    assert counted >= 20, (counted, seconds["render"])


def test_two_renders_in_two_threads_overlap(big_scene):
    # Each render's progress, as its thread sees it: with the GIL held for a
    # whole render, the second would not start before the first had ended.
    seen = {0: [], 1: []}

    def one(which):
        whitted.render(big_scene, spp=64, threads=1,
                       progress=lambda f: seen[which].append((time.perf_counter(), f)))

    workers = [threading.Thread(target=one, args=(k,)) for k in (0, 1)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    end = {k: max(t for t, _ in seen[k]) for k in seen}
    for k in seen:
        other = 1 - k
        during = [f for t, f in seen[k] if t < end[other] and 0 < f < 1]
        assert during, f"render {k} made no progress while render {other} ran"


def test_ctrl_c_raises_keyboard_interrupt_within_a_tile(big_scene):
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        whitted.render(big_scene, spp=1024)  # several seconds, had it gone on
    assert time.perf_counter() - start < 2.0
    # The module still renders afterwards.
    assert whitted.render(big_scene, width=16, height=12).shape == (12, 16, 3)


def test_progress_is_called_in_the_calling_thread_up_to_one(big_scene):
    calls = []
    whitted.render(big_scene, spp=4,
                   progress=lambda f: calls.append((threading.get_ident(), f)))
    assert calls, "never called"
    assert {ident for ident, _ in calls} == {threading.get_ident()}
    fractions = [f for _, f in calls]
    assert fractions == sorted(fractions)
    assert fractions[-1] == 1.0


def test_an_exception_in_progress_stops_the_render_and_is_raised(big_scene):
    def give_up(fraction):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        whitted.render(big_scene, spp=64, progress=give_up)


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_a_thousand_renders_leave_memory_flat(seed_path):
    scene = whitted.load(seed_path)
    for _ in range(100):
        whitted.render(scene, width=32, height=24, return_stats=True)
    before = resident_bytes()
    for _ in range(1000):
        whitted.render(scene, width=32, height=24, return_stats=True)
    assert resident_bytes() - before < 4 << 20
