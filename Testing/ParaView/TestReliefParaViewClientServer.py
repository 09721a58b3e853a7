"""Client and server: pvserver on 2 MPI ranks at 127.0.0.1, pvpython connected to it, the
plugin loaded on both sides; the server's ranks render the brick wall, its cells split
between them (remote rendering forced: ParaView would draw data this small on the client),
IceT composites their images, and the client saves the screenshot. It must match the
committed baseline (the same scene in one process), as the pvbatch test's images do.

  python3 TestReliefParaViewClientServer.py PLUGIN DATA BASELINE OUTPUT_DIR
"""
import json
import os
import socket
import subprocess
import sys
import threading

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import relief_paraview_images as images  # noqa: E402
import relief_paraview_programs as programs  # noqa: E402

plugin, data, baseline, output = sys.argv[1:5]
render = os.path.join(os.path.dirname(os.path.abspath(__file__)), "relief_paraview_render.py")
mpiexec = programs.MPIEXEC
pvserver = programs.program("pvserver")
pvpython = programs.program("pvpython")
image = os.path.join(output, "TestReliefParaViewClientServer.png")

with socket.socket() as probe:  # a port nobody listens on
    probe.bind(("127.0.0.1", 0))
    port = probe.getsockname()[1]
server = subprocess.Popen(mpiexec + ["-n", "2", pvserver, "--force-offscreen-rendering",
                                     "--hostname=127.0.0.1", "--server-port=%d" % port],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          errors="replace")
listening = threading.Event()


def relay():
    """pvserver's output, into the test's log; the event once it listens."""
    for line in server.stdout:
        print("pvserver:", line.rstrip(), flush=True)
        if "Accepting connection" in line:
            listening.set()


threading.Thread(target=relay, daemon=True).start()
failures = []
try:
    for _ in range(120):
        if listening.wait(timeout=1) or server.poll() is not None:
            break
    if not listening.is_set():
        raise RuntimeError("pvserver exited or did not listen within 2 minutes (port %d)" % port)
    subprocess.run([pvpython, "--force-offscreen-rendering", render, "--plugin", plugin,
                    "--data", data, "--output", image, "--redistribute", "--server", str(port)],
                   check=True, timeout=300)
    with open(os.path.splitext(image)[0] + ".json") as report:
        facts = json.load(report)
    if facts["ranks_with_cells"] != 2:
        failures.append("the cells lie on %d of the server's 2 ranks" % facts["ranks_with_cells"])
    if facts["messages"]:
        failures.append("messages: %s" % facts["messages"])
    share = images.differing_pixels(images.load_png(image), images.load_png(baseline), 8)
    print("client-server against the baseline: %.4f%% differ by more than 8" % (100 * share))
    if share > 0.001:
        failures.append("the screenshot differs from the baseline in %.3f%%" % (100 * share))
finally:
    programs.stop(server)
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
