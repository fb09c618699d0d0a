"""What the stereo-view tests share: a private bus of real processes, recorded
by lcm-logger, and polling with a deadline."""
import os
import random
import secrets
import signal
import socket
import subprocess
import time
import urllib.request

import pytest

import widestereo

SOURCE = os.environ.get("WS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("WS_BINARY_DIR", os.path.join(SOURCE, "build"))
BIN = os.path.join(BUILD, "bin")
CALIBRATION = os.path.join(SOURCE, "config", "calib", "sim-default.yaml")


def until(condition, timeout, what):
    """Polls condition() until it is true (returns its value) or fails the test after timeout seconds."""
    end = time.monotonic() + timeout
    while True:
        value = condition()
        if value:
            return value
        if time.monotonic() > end:
            pytest.fail("after %.0f s still not: %s" % (timeout, what))
        time.sleep(0.1)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Bus:
    """Processes on a private udpm bus, each with its output in the test's folder, and a recording."""

    def __init__(self, folder, channels):
        self.folder = str(folder)
        # Ports apart from the other tests' (tests/support UniqueUdpmUrl: 20000 to 39999).
        self.url = "udpm://239.255.76.67:%d?ttl=0&recv_buf_size=16777216" % random.randrange(41000, 49000)
        self.log = os.path.join(self.folder, "bus.lcmlog")
        self.processes = []
        self.start("lcm-logger", ["-f", "-s", "--channel=" + channels, "--lcm-url=" + self.url, self.log], own=False)

    def start(self, name, args, own=True):
        executable = os.path.join(BIN, name) if own else name
        argv = [executable] + args
        if own:
            argv += ["--in-url", self.url, "--out-url", self.url, "--log-dir", self.folder]
        out = open(os.path.join(self.folder, "%s-%d.out" % (os.path.basename(name), len(self.processes))), "w")
        process = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, cwd=SOURCE)
        self.processes.append((name, process, out.name))
        return process

    def page(self, port, process):
        """Waits for stereo-view to serve its page; its address."""
        address = "http://127.0.0.1:%d/" % port

        def up():
            assert process.poll() is None, "stereo-view ended: " + self.output("stereo-view")
            try:
                return urllib.request.urlopen(address, timeout=1).status == 200
            except OSError:
                return False
        until(up, 30, "stereo-view serves " + address)
        return address

    def output(self, name):
        return "\n".join(open(path).read() for n, _, path in self.processes if n == name)

    def stop(self):
        for _, process, _ in reversed(self.processes):
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
        for name, process, path in reversed(self.processes):
            try:
                process.wait(timeout=15)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()

    def events(self, channel):
        return [e.message for e in widestereo.read_log(self.log, channels={channel})]


def key_file(folder):
    path = os.path.join(str(folder), "rig.key")
    with os.fdopen(os.open(path, os.O_WRONLY | os.O_CREAT, 0o600), "wb") as f:
        f.write(secrets.token_bytes(32))
    return path
