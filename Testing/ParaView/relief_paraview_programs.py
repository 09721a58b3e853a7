"""ParaView's programs as the test drivers start and stop them (in /usr/bin/python3)."""
import os
import subprocess


def program(name):
    """The program CMake found (Testing/ParaView/CMakeLists.txt), else the one on PATH."""
    return os.environ.get("RELIEF_" + name.upper(), name)


# --oversubscribe: 2 ranks even on a machine of fewer cores
MPIEXEC = [program("mpiexec"), "--oversubscribe"] + \
    (["--allow-run-as-root"] if os.geteuid() == 0 else [])


def stop(process):
    """Ends a program started in the background, killing it if it does not end."""
    process.terminate()
    try:
        process.wait(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
