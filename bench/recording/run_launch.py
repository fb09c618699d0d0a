"""One run launch's recording (bench/recording/run_launch.sh): its size a
minute and a pair, the pairs a second captured and matched, and the depth
chain's latency: when lcm-logger received each STEREO_DISPARITY and
CLOUD_STATS, minus the capture utime of the pair it is of (both clocks the
host's).

    run_launch.py RUN_DIR LABEL"""
import glob
import os
import statistics
import sys

import widestereo

run, label = sys.argv[1], sys.argv[2]
logs = sorted(glob.glob(os.path.join(run, "run.lcmlog*")))
size = sum(os.path.getsize(log) for log in logs)
times, pairs, latency = [], 0, {"STEREO_DISPARITY": [], "CLOUD_STATS": []}
for log in logs:
    for event in widestereo.read_log(log, channels={"STEREO_IMAGES", *latency}):
        times.append(event.utime)
        if event.channel == "STEREO_IMAGES":
            pairs += 1
        else:
            latency[event.channel].append((event.utime - event.message.utime) / 1000)
span_s = (max(times) - min(times)) / 1e6
print(f"| {label} | {size / 1e6 / span_s * 60:.0f} | {size / 1e6 / pairs:.2f} | {pairs / span_s:.2f} | "
      f"{len(latency['STEREO_DISPARITY']) / span_s:.2f} | "
      f"{statistics.median(latency['STEREO_DISPARITY']):.0f} | {statistics.median(latency['CLOUD_STATS']):.0f} |")
