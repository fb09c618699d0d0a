#!/usr/bin/python3
# The per-camera rows of a stereo-calibrate report (the published model):
# model, views, outliers and their share of the corners, fitted RMS (per
# corner) and the k-fold held-out RMS the report carries.
#   report_rows.py REPORT.json LABEL
import json
import sys

report = json.load(open(sys.argv[1]))
label = sys.argv[2]
if "models" in report:  # several models solved: the chosen one is published
    chosen = report.get("chosen")
    report = next(m for m in report["models"] if m.get("model") == chosen)
for camera in report["cameras"]:
    outliers, points = camera.get("outliers", 0), camera.get("points", 0)
    share = 100.0 * outliers / (outliers + points) if outliers + points else 0.0
    print("%s %-5s %s: RMS %.4f px over %d views, %d outliers = %.1f %%, k-fold held out %s px"
          % (label, camera["name"], report.get("model", "?"), camera["rms_px"], camera["views"], outliers,
             share, "%.4f" % camera["heldout_rms_px"] if "heldout_rms_px" in camera else "-"))
