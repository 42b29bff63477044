"""The module's own contract: a docstring on everything public, the GIL released in long calls."""
import inspect
import sys
import threading
import time

import foldkit


def public(obj):
    return [(n, getattr(obj, n)) for n in dir(obj) if not n.startswith("_")]


def doc_text(obj):
    """The docstring without pybind11's signature lines."""
    doc = inspect.getdoc(obj) or ""
    return "\n".join(line for line in doc.splitlines() if not line.startswith(obj.__name__ + "(") and "->" not in line).strip() \
        if hasattr(obj, "__name__") else doc.strip()


def test_every_public_name_has_a_docstring():
    missing = []
    for module in (foldkit, foldkit.generators):
        for name, obj in public(module):
            if inspect.ismodule(obj) and obj is not foldkit.generators:
                continue
            if callable(obj) and not doc_text(obj):
                missing.append(f"{module.__name__}.{name}")
            if inspect.isclass(obj) and obj.__module__.startswith("foldkit"):
                for attr, member in vars(obj).items():
                    if attr.startswith("_"):
                        continue
                    if not (inspect.getdoc(member) or "").strip():
                        missing.append(f"{name}.{attr}")
    assert not missing, missing


def test_long_calls_release_the_gil():
    # With a 10 s switch interval, a call that held the GIL would keep this thread from running
    # until it returned, so the count read right after the call would not have moved.
    p = foldkit.generators.miura(20, 20)
    inside, done = threading.Event(), threading.Event()
    counter, seen = [0], []

    def work():
        inside.set()
        foldkit.fold(p, fraction=0.9, collisions=True, replay=False)  # about 0.7 s
        seen.append(counter[0])
        done.set()

    old = sys.getswitchinterval()
    sys.setswitchinterval(10.0)
    try:
        t = threading.Thread(target=work)
        t.start()
        inside.wait()
        while not done.is_set():
            counter[0] += 1
            if counter[0] % 1000 == 0:
                time.sleep(0)  # lets the worker back in once its call has returned
        t.join()
    finally:
        sys.setswitchinterval(old)
    assert seen[0] > 1000, seen
