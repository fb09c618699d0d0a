#!/usr/bin/python3
"""A page on another machine, for the transport benchmark: reads stereo-view's
event stream for the depth view (/events?view=depth) and fetches every image
and cloud its events name, as the page does, but draws nothing, so the rig's
cores pay only what stereo-view itself does for a browser elsewhere. Runs at
nice 19 until Ctrl-C (the launcher's stop), then prints what it fetched and
the CPU it took.
    bench/transport/page_reader.py http://127.0.0.1:PORT/ [--log-dir DIR] [--quiet] ..."""
import json
import os
import signal
import sys
import time
import urllib.error
import urllib.request

# The depth view's topics whose events name payloads, and the keys naming them.
PAYLOADS = {"rectified": ("left", "right"), "disparity": ("src",), "cloud": ("src",)}


def open_stream(url):
    for _ in range(300):  # stereo-view starts beside it
        try:
            return urllib.request.urlopen(url + "events?view=depth", timeout=10)
        except OSError:
            time.sleep(0.1)
    sys.exit("page reader: no stereo-view at " + url)


def main():
    os.nice(19)
    url = next(a for a in sys.argv[1:] if a.startswith("http"))
    signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt))
    stream = open_stream(url)
    print("page reader: reading the depth view of", url, flush=True)
    start, start_cpu = time.monotonic(), time.process_time()
    events = fetched = size = 0
    topic = None
    try:
        for raw in stream:
            line = raw.decode("utf-8").rstrip("\n")
            if line.startswith("event: "):
                topic = line[len("event: "):]
            elif line.startswith("data: ") and topic in PAYLOADS:
                events += 1
                event = json.loads(line[len("data: "):])
                for key in PAYLOADS[topic]:
                    try:
                        size += len(urllib.request.urlopen(url + event[key], timeout=5).read())
                        fetched += 1
                    except urllib.error.HTTPError:  # forgotten already: the next event names a newer one
                        pass
    except KeyboardInterrupt:
        pass
    wall, cpu = time.monotonic() - start, time.process_time() - start_cpu
    print("page reader: %d events, %d payloads fetched (%.1f MB) in %.1f s; it took %.0f %% of one core "
          "(at nice 19)" % (events, fetched, size / 1e6, wall, 100 * cpu / wall), flush=True)


if __name__ == "__main__":
    main()
