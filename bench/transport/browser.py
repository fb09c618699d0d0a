#!/usr/bin/python3
"""One browser on stereo-view's page for the transport benchmark: Debian's
headless Chromium (Selenium) opens the page's depth view and keeps it open,
reading every update, until Ctrl-C (the launcher's stop): a browser on the
rig itself (page_reader.py stands for one on another machine). It runs at
the lowest priority (nice 19), so that the rig's processes go first on the
shared cores. At the end it prints the CPU its Chromium took, which a
browser elsewhere would not take from the rig.
    bench/transport/browser.py http://127.0.0.1:PORT/ [--log-dir DIR] [--quiet] ..."""
import os
import signal
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By


def descendants(pid):
    """pid and every process below it."""
    children = {}
    for entry in os.listdir("/proc"):
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            children.setdefault(int(fields[1]), []).append(int(entry))
        except (OSError, ValueError, IndexError):
            continue
    found, todo = [], [pid]
    while todo:
        p = todo.pop()
        found.append(p)
        todo.extend(children.get(p, []))
    return found


def cpu_seconds(pid):
    """User + system CPU seconds of pid and every process below it (those alive)."""
    total = 0
    for p in descendants(pid):
        try:
            with open("/proc/%d/stat" % p) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
        except (OSError, ValueError, IndexError):
            continue
    return total / os.sysconf("SC_CLK_TCK")


def main():
    os.nice(19)
    url = next(a for a in sys.argv[1:] if a.startswith("http"))
    options = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,1200",
                 "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                 # WebGL in SwiftShader, the page composited in software: SwiftShader's
                 # compositing alone took two thirds of a core here.
                 "--disable-gpu-compositing"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    stop = []
    signal.signal(signal.SIGINT, lambda *_: stop.append(1))
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    try:
        for _ in range(300):  # stereo-view starts beside it
            try:
                driver.get(url)
                break
            except Exception:
                time.sleep(0.1)
        driver.find_element(By.ID, "tab-depth").click()
        print("browser: showing the depth view of", url, flush=True)
        pid, start, start_cpu = driver.service.process.pid, time.monotonic(), None
        while not stop:
            time.sleep(0.2)
            if start_cpu is None and time.monotonic() - start > 2:  # the page loaded and drawn
                start, start_cpu = time.monotonic(), cpu_seconds(pid)
        if start_cpu is not None:
            used, wall = cpu_seconds(pid) - start_cpu, time.monotonic() - start
            print("browser: Chromium took %.1f s of CPU in %.1f s (%.0f %% of one core, at nice 19)"
                  % (used, wall, 100 * used / wall), flush=True)
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
