"""Replays a pqevents GUI test script in a client/server session: starts `pvserver` (with the
plugin) on a free port, runs the `paraview` client connected to it with the script, stops the
server, and exits with the client's code. The client's output goes to stdout, for ctest's
FAIL_REGULAR_EXPRESSION.

Run (plain python3; ctest does it, see Testing/PanelGUI.cmake):
  python3 run_gui_client_server.py PVSERVER PARAVIEW PLUGIN_DIR SCRIPT.xml TEST_DIR"""
import os
import re
import subprocess
import sys
import threading
import time

STARTUP = 60  # seconds for pvserver to listen
CLIENT_TIMEOUT = 300  # seconds


def forward(stream):
    for line in stream:
        print("pvserver: " + line.rstrip())


def main():
    pvserver, paraview, plugin_dir, script, test_dir = sys.argv[1:6]
    env = dict(os.environ, PV_PLUGIN_PATH=plugin_dir)
    server = subprocess.Popen(
        [pvserver, "--force-offscreen-rendering", "--server-port=0", "--plugins=PsiVolume"],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        port = None
        deadline = time.time() + STARTUP
        for line in server.stdout:
            print("pvserver: " + line.rstrip())
            match = re.search(r"Accepting connection\(s\): [^:\s]+:(\d+)", line)
            if match:
                port = int(match.group(1))
                break
            if time.time() > deadline:
                break
        if port is None:
            print("FAILED: pvserver did not report a port")
            return 1
        # Keep draining the server's output, so that it never blocks on a full pipe.
        threading.Thread(target=forward, args=(server.stdout,), daemon=True).start()
        sys.stdout.flush()
        client = subprocess.run(
            [paraview, "--dr", "--url=cs://localhost:%d" % port,
             "--plugin-search-paths=" + plugin_dir, "--plugins=PsiVolume",
             "--test-script=" + script, "--test-directory=" + test_dir, "--exit"],
            timeout=CLIENT_TIMEOUT)
        print("paraview exited with %d" % client.returncode)
        return client.returncode
    finally:
        try:
            server.wait(timeout=20)  # pvserver exits when its client disconnects
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


if __name__ == "__main__":
    sys.stdout.reconfigure(line_buffering=True)
    sys.exit(main())
