"""stereo-view's page in Debian's headless Chromium (Selenium), over real LCM:
the simulated rig's processes on a bus of their own (udpm, ttl 0), lcm-logger
recording it, and the page checked against what the bus carried."""
import json
import os
import re
import signal
import socket
import time
import urllib.error
import urllib.request

import cv2
import numpy as np
import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

import widestereo
from view_support import BIN, CALIBRATION, free_port, key_file, until


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,1200",
                 "--enable-unsafe-swiftshader", "--use-angle=swiftshader",
                 # WebGL in SwiftShader, the page composited in software: SwiftShader's
                 # compositing alone took two thirds of a core here.
                 "--disable-gpu-compositing"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.set_script_timeout(120)  # a loaded machine's renderer may lag behind
    yield driver
    driver.quit()


def attribute(driver, selector, name):
    return driver.find_element(By.CSS_SELECTOR, selector).get_attribute(name)


def green_pixels(png):
    image = cv2.imdecode(np.frombuffer(png, np.uint8), cv2.IMREAD_COLOR)
    b, g, r = image[:, :, 0].astype(int), image[:, :, 1].astype(int), image[:, :, 2].astype(int)
    return int(np.count_nonzero((g > 180) & (r < 90) & (b < 90)))


def post_command(driver, body):
    """POSTs a command as the page does; the HTTP status."""
    return driver.execute_async_script("""
        const done = arguments[arguments.length - 1];
        fetch('command', {method: 'POST', headers: {'X-Widestereo-Page': '1', 'Content-Type': 'application/json'},
                          body: JSON.stringify(arguments[0])}).then(r => done(r.status));""", body)


def screenshot(driver, bus, name, element=None):
    """The window as it is, or scrolled to show the element of that id first."""
    if element:
        driver.execute_script("document.getElementById(arguments[0]).scrollIntoView();", element)
    path = os.path.join(bus.folder, name)
    driver.save_screenshot(path)
    return path


@pytest.mark.recorded("STEREO_COMMAND")
def test_calibration_view_coaches_and_sends_commands_only_with_the_key(bus, browser, tmp_path):
    key = key_file(tmp_path)
    report = os.path.join(bus.folder, "report.json")
    # A keyed rig: every process has the key (images and corners are signed).
    # The pages first, so that they hear every frame; the images PNG, as the
    # calibrate launch records them, decoded by every process.
    keyed_port, open_port = free_port(), free_port()
    keyed = bus.start("stereo-view", ["--port", str(keyed_port), "--key-file", key])
    readonly = bus.start("stereo-view", ["--port", str(open_port)])
    keyed_page, readonly_page = bus.page(keyed_port, keyed), bus.page(open_port, readonly)  # listening
    bus.start("stereo-capture", ["--source", "sim:config/sim/default.yaml", "--rate", "2", "--loop", "--key-file", key,
                                 "--compression", "png"])
    bus.start("stereo-detect", ["--board", "chessboard:9x6:0.05", "--key-file", key])
    # The quickest solve: one model, no non-radial field or board bow to choose.
    bus.start("stereo-calibrate", ["--model", "poly6", "--nonradial", "none", "--board-warp", "off", "--out", os.path.join(bus.folder, "calib.yaml"),
                                   "--report", report, "--key-file", key, "--preview-every", "1"])

    # Both images, the corners drawn on them (in the DOM and in the pixels).
    browser.get(keyed_page)

    def corners_drawn(side):  # the page redraws at every frame: both checks at one moment
        canvas = browser.find_element(By.CSS_SELECTOR, "#cam-%s canvas" % side)
        return green_pixels(canvas.screenshot_as_png) > 50 and int(attribute(browser, "#cam-" + side, "data-corners")) > 0
    until(lambda: corners_drawn("left") and corners_drawn("right"), 180, "corners drawn on both images")

    # The coverage grows as views are accepted.
    until(lambda: int(attribute(browser, "#cam-left", "data-coverage")) > 0, 60, "coverage shown")
    first = int(attribute(browser, "#cam-left", "data-coverage"))
    until(lambda: int(attribute(browser, "#cam-left", "data-coverage")) > first, 180, "the coverage grows")
    screenshot(browser, bus, "calibration-collecting.png")

    # camera_calibration's bars: x, y, size, skew of the boards found; "enough" lights Solve.
    until(lambda: int(browser.find_element(By.ID, "spread-boards").text) > 1, 60, "boards measured")
    bars = browser.execute_script(
        "return [...document.querySelectorAll('#spread .track')].map(t => [t.dataset.name, +t.dataset.progress]);")
    assert [name for name, _ in bars] == ["x", "y", "size", "skew"]
    assert all(0 <= p <= 1 for _, p in bars) and any(p > 0 for _, p in bars), bars
    filled = browser.execute_script(
        "return Math.max(...[...document.querySelectorAll('#spread .fill')].map(f => f.getBoundingClientRect().width));")
    assert filled > 10, "the bars are drawn filled, not only counted"
    boards = int(browser.find_element(By.ID, "spread-boards").text)
    views_stereo = browser.execute_script("return state.coverage && state.coverage.views_stereo")
    enough = (all(p >= 1 for _, p in bars) or boards >= 40) and views_stereo > 0
    until(lambda: attribute(browser, "#spread", "data-enough") == str(enough).lower() or
          int(browser.find_element(By.ID, "spread-boards").text) != boards, 5, "enough as the bars say")
    assert ("ready" in attribute(browser, "button[data-command=solve]", "class")) == \
        (attribute(browser, "#spread", "data-enough") == "true")

    # Without the key: the buttons are disabled, say why, and the server sends nothing.
    browser.get(readonly_page)
    until(lambda: "rig key" in browser.find_element(By.ID, "command-why").text, 20, "the page says why it is read-only")
    until(lambda: browser.find_elements(By.CSS_SELECTOR, "#view-list .view-card button.remove"), 20, "the views listed")
    assert browser.execute_script(  # one look: the list is drawn anew as views come
        "return [...document.querySelectorAll('button.command, button.remove')].every(b => b.disabled);")
    for body in ({"command": "solve"}, {"command": "remove", "frame": 1, "utime": 1}):
        assert post_command(browser, body) == 403

    # With it: solve from the page, accepted by the keyed stereo-calibrate.
    browser.get(keyed_page)
    until(lambda: browser.find_element(By.CSS_SELECTOR, "button[data-command=solve]").is_enabled(), 20,
          "the solve button enabled")
    until(lambda: int(attribute(browser, "#cam-left", "data-coverage")) > 0, 30, "coverage shown")
    # Before the solve, the uncertainty of a quick solve of the views so far, per camera.
    until(lambda: len(browser.find_elements(By.CSS_SELECTOR, "#preview .maps canvas")) == 2, 60,
          "the views' uncertainty before a solve")
    assert browser.find_element(By.ID, "preview").is_displayed() and attribute(browser, "#preview-model", "textContent") == "poly6"
    screenshot(browser, bus, "calibration-preview.png", "preview")
    browser.find_element(By.CSS_SELECTOR, "button[data-command=solve]").click()
    row = until(lambda: browser.find_elements(By.CSS_SELECTOR, "#models tr.chosen"), 300, "the model table")[0]
    screenshot(browser, bus, "calibration-solved.png")
    with open(report) as f:
        solved = json.load(f)
    assert row.get_attribute("data-model") == solved["model"]
    assert float(row.get_attribute("data-stereo-rms")) == solved["stereo"]["rms_px"]
    assert float(row.get_attribute("data-left-rms")) == solved["cameras"][0]["rms_px"]
    maps = browser.find_elements(By.CSS_SELECTOR, "#maps canvas")
    assert len(maps) == 4, "residual and uncertainty maps of both cameras"
    assert all(m.is_displayed() for m in maps)
    until(lambda: not browser.find_element(By.ID, "preview").is_displayed(), 10, "the preview gives way to the solve")
    # The solved calibration as the rig uses it: K, the distortion, R, T and the baseline.
    until(lambda: attribute(browser, "#baseline", "data-metres"), 60, "the calibration in use")
    assert float(attribute(browser, "#baseline", "data-metres")) == pytest.approx(solved["stereo"]["baseline_m"], rel=1e-9)
    intrinsics = browser.find_elements(By.CSS_SELECTOR, "#intrinsics tbody tr")
    assert [r.get_attribute("data-camera") for r in intrinsics] == ["left", "right"]
    assert all(r.find_elements(By.TAG_NAME, "td")[1].text == solved["model"] for r in intrinsics)
    screenshot(browser, bus, "calibration-solved-calibration.png")

    # The views, oldest last, each with its RMS in the solve (the report's), the
    # newest with a thumbnail of the frame the page was shown.
    until(lambda: browser.find_elements(By.CSS_SELECTOR, "#view-list .view-card[data-left-rms]"), 30, "the views' RMS")
    # One look (the list is drawn anew as views come).
    listed = browser.execute_script("""
        const cards = [...document.querySelectorAll('#view-list .view-card')].reverse();
        const rms = (v) => v === undefined ? null : Number(v);
        return {count: +document.querySelector('#view-list').dataset.views,
                views: cards.map(c => [rms(c.dataset.leftRms), rms(c.dataset.rightRms)])};""")
    assert listed["count"] == len(listed["views"])
    solved_rms = [list(pair) for pair in zip(solved["cameras"][0]["view_rms"], solved["cameras"][1]["view_rms"])]
    assert listed["views"][:len(solved_rms)] == solved_rms
    # Every view has its thumbnail, those accepted while no page showed this
    # stereo-view's calibration view (the read-only one's was shown) too.
    def without_thumbnail():
        return browser.execute_script("""
            const cards = [...document.querySelectorAll('#view-list .view-card')];
            return cards.length ? cards.filter(c => c.querySelector('canvas').dataset.image !== '1')
                                       .map(c => +c.dataset.frameId) : null;""")
    try:
        until(lambda: without_thumbnail() == [], 30, "every view's thumbnail drawn")
    except BaseException:
        print("the views of these frames have no thumbnail:", without_thumbnail())
        raise
    screenshot(browser, bus, "calibration-views.png", "view-list")

    # Remove the newest view: stereo-calibrate takes it out of its list and of its views file.
    frame_id, utime = browser.execute_script("""
        const card = document.querySelector('#view-list .view-card');
        card.querySelector('button.remove').click();
        return [+card.dataset.frameId, +card.dataset.utime];""")
    shown = "#view-list .view-card[data-frame-id='%d'][data-utime='%d']" % (frame_id, utime)
    until(lambda: not browser.find_elements(By.CSS_SELECTOR, shown), 30, "the removed view gone from the list")
    assert "remove frame %d sent" % frame_id in browser.find_element(By.ID, "command-why").text
    # The page's list, kept by the changes since the whole list it got first,
    # is the whole list a new stream gets now.
    def lists_agree():
        return browser.execute_async_script("""
            const done = arguments[arguments.length - 1], stream = new EventSource('events');
            stream.addEventListener('views', (e) => {
              stream.close();
              const text = (v) => v && JSON.stringify([v.frame_id, v.utime, v.thumbnail, v.left_rms, v.right_rms]);
              const whole = JSON.parse(e.data).views.map(text);
              const shown = [...document.querySelectorAll('#view-list .view-card')].map(
                  c => text(viewList.views.get(`${c.dataset.frameId}:${c.dataset.utime}`)));
              done(whole.length > 0 && viewList.views.size === whole.length &&
                   JSON.stringify(whole) === JSON.stringify(shown));
            });""")
    until(lists_agree, 30, "the page's list as a new stream's whole list")

    bus.stop()
    views_file = os.path.join(bus.folder, "stereo-calibrate-views.lcmlog")
    kept = [(c.frame_id, c.utime) for c in (e.message for e in widestereo.read_log(views_file))]
    removed = [(c.frame_id, c.utime) for c in (e.message for e in widestereo.read_log(
        os.path.join(bus.folder, "stereo-calibrate-views-removed.lcmlog")))]
    assert (frame_id, utime) not in kept and len(kept) >= len(listed["views"]) - 1 and removed == [(frame_id, utime)]
    commands = bus.events("STEREO_COMMAND")
    senders = [c.auth.sender for c in commands]
    assert not [s for s in senders if " pid %d" % readonly.pid in s], "the read-only stereo-view sent a command"
    assert len(commands) == 2 and all(" pid %d" % keyed.pid in s for s in senders), senders
    assert commands[0].command == "solve" and commands[0].auth.key_id != 0
    assert commands[1].command == "remove" and list(commands[1].args) == ["frame=%d" % frame_id, "utime=%d" % utime]


def listed_views(port, enough, timeout):
    """The page's views list as one event stream keeps it (the whole list,
    then its changes), once `enough(views)` holds."""
    views, topic, deadline = {}, None, time.time() + timeout
    with urllib.request.urlopen("http://127.0.0.1:%d/events?view=calibration" % port, timeout=10) as stream:
        for line in stream:
            line = line.decode().rstrip("\n")
            if line.startswith("event: "):
                topic = line[len("event: "):]
            elif line.startswith("data: ") and topic == "views":
                update = json.loads(line[len("data: "):])
                if "views" in update:
                    views = {}
                for view in update.get("views", []) + update.get("put", []):
                    views[(view["frame_id"], view["utime"])] = view
                for key in update.get("gone", []):
                    views.pop(tuple(key), None)
                if enough(views):
                    return list(views.values())
            assert time.time() < deadline, "the views listed: %d" % len(views)


@pytest.mark.recorded("STEREO_THUMBNAILS|STEREO_CORNERS|CALIBRATION_VIEWS")
def test_thumbnails_every_view_has_one_though_this_page_heard_no_image(bus):
    # The images go from stereo-capture to stereo-detect on a bus of their
    # own: stereo-view drops every image message, as a loaded one drops some,
    # and still draws each view with the thumbnail stereo-detect sent.
    bus_port = int(re.search(r":(\d+)\?", bus.url).group(1))
    images_url = bus.url.replace(":%d?" % bus_port, ":%d?" % (bus_port + 1))
    port = free_port()
    view = bus.start("stereo-view", ["--port", str(port)])
    bus.page(port, view)
    bus.start(os.path.join(BIN, "stereo-capture"), ["--source", "sim:config/sim/default.yaml", "--rate", "2", "--loop",
                                                    "--out-url", images_url, "--log-dir", bus.folder], own=False)
    bus.start(os.path.join(BIN, "stereo-detect"), ["--board", "chessboard:9x6:0.05", "--in-url", images_url,
                                                   "--out-url", bus.url, "--log-dir", bus.folder], own=False)
    bus.start("stereo-calibrate", ["--model", "poly6", "--nonradial", "none", "--board-warp", "off",
                                   "--out", os.path.join(bus.folder, "calib.yaml")])
    views = listed_views(port, lambda views: len(views) >= 3, 180)
    assert [v["frame_id"] for v in views if not v["thumbnail"]] == [], "views without a thumbnail"
    thumbnail = urllib.request.urlopen("http://127.0.0.1:%d/%s" % (port, views[0]["thumbnail"]), timeout=10).read()
    image = cv2.imdecode(np.frombuffer(thumbnail, np.uint8), cv2.IMREAD_UNCHANGED)
    assert image.shape[1] == 128 and image.shape[0] == 96
    bus.stop()
    thumbnails = bus.events("STEREO_THUMBNAILS")
    assert thumbnails and all((t.left.width, t.right.width) == (128, 0) for t in thumbnails)
    boards = {c.frame_id for c in bus.events("STEREO_CORNERS") if c.left.n > 0 or c.right.n > 0}
    assert boards and boards <= {t.frame_id for t in thumbnails}, "a frame with a board and no thumbnail"


def view_counters(bus, pid):
    """stereo-view's heartbeats: (utime, {channel: counters})."""
    return [(s.utime, {c.channel: c for c in s.channels}) for s in bus.events("PROCESS_STATUS")
            if s.name == "stereo-view" and s.pid == pid]


@pytest.mark.recorded("CLOUD_STATS|PROCESS_STATUS|STEREO_DISPARITY")
def test_depth_view_shows_what_the_bus_carries_and_a_stalled_browser_costs_nothing(bus, browser):
    bus.start("stereo-capture", ["--source", "sim:config/sim/wall.yaml", "--rate", "5", "--loop"])
    bus.start("stereo-match", ["--config", "config/stereo-match-live.yaml", "--calib", CALIBRATION])
    bus.start("stereo-cloud", ["--config", "config/stereo-cloud-live.yaml"])
    port = free_port()
    view = bus.start("stereo-view", ["--port", str(port), "--calib", CALIBRATION])
    browser.get(bus.page(port, view))
    browser.find_element(By.ID, "tab-depth").click()
    until(lambda: browser.find_elements(By.CSS_SELECTOR, "#legend span"), 60, "the disparity's legend")
    until(lambda: attribute(browser, "#cloud-points", "data-frame-id"), 60, "the cloud's statistics")
    assert not browser.find_element(By.CSS_SELECTOR, "#cloud-stats-age + .waiting").is_displayed(), \
        "what the panel waited for has come"
    until(lambda: attribute(browser, "#cloud", "data-shown"), 60, "the cloud in 3-D")
    # As rviz: axes, a grid, both cameras' frustums; a clicked point's coordinates and range; the cloud's rate.
    until(lambda: {"axes", "grid", "frustum-left", "frustum-right", "plane"} <=
          set((attribute(browser, "#cloud", "data-helpers") or "").split()), 30, "axes, grid and frustums")
    clicked = [0.0]

    def click_and_pick():  # the page reflows as panels fill: a click may land off the cloud, so again after 2 s
        if time.monotonic() - clicked[0] > 2:
            ActionChains(browser).move_to_element(browser.find_element(By.CSS_SELECTOR, "#cloud canvas")).click().perform()
            clicked[0] = time.monotonic()
        return attribute(browser, "#picked", "data-range")
    until(click_and_pick, 20, "the point under the click picked")
    x, y, z, r = (float(attribute(browser, "#picked", "data-" + k)) for k in ("x", "y", "z", "range"))
    assert r == pytest.approx((x * x + y * y + z * z) ** 0.5, rel=1e-9) and z > 0
    assert "range" in browser.find_element(By.ID, "picked").text
    until(lambda: "clouds/s" in browser.find_element(By.ID, "cloud-rate").text, 30, "the clouds' rate")
    assert attribute(browser, "#cloud-figure .age", "data-age-s") is not None
    until(lambda: attribute(browser, "#rect-right canvas", "width") != "640" or
          "frame" in browser.find_element(By.CSS_SELECTOR, "#rect-right .info").text, 60, "the rectified pair")
    shown = browser.execute_script("""
        const p = document.querySelector('#cloud-points').dataset, l = document.querySelector('#legend');
        return {frame: p.frameId, points: p.points, offset: p.planeOffset, f: l.dataset.f,
                baseline: l.dataset.baseline,
                ticks: [...l.querySelectorAll('span')].map(s => [s.dataset.disparity, s.dataset.metres])};""")
    screenshot(browser, bus, "depth.png")
    src = browser.execute_script("return document.querySelector('#disparity').src")
    assert "/blob/" in src and urllib.request.urlopen(src, timeout=5).headers["Content-Type"] == "image/jpeg"
    with pytest.raises(urllib.error.HTTPError, match="404"):
        urllib.request.urlopen("http://127.0.0.1:%d/blob/999999999" % port, timeout=5)
    with pytest.raises(urllib.error.HTTPError, match="400"):
        urllib.request.urlopen("http://127.0.0.1:%d/events?view=everything" % port, timeout=5)

    # While the page shows depth, stereo-view makes no images of the calibration view.
    calibration_frame = attribute(browser, "#cam-left", "data-frame-id")
    first = int(attribute(browser, "#disparity-figure", "data-frame-id"))
    until(lambda: int(attribute(browser, "#disparity-figure", "data-frame-id")) >= first + 10, 60,
          "ten frames more of the depth view")
    assert attribute(browser, "#cam-left", "data-frame-id") == calibration_frame

    # A second stereo-view on the same port is refused, not handed half the browsers.
    second = bus.start("stereo-view", ["--port", str(port)])
    assert second.wait(timeout=30) == 1
    assert "cannot listen on 127.0.0.1:%d" % port in bus.output("stereo-view")

    # A browser that stops reading: its events are skipped, the input goes on.
    stalled = socket.socket()
    stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stalled.connect(("127.0.0.1", port))
    stalled.sendall(b"GET /events HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n\r\n" % port)
    stalled_at = time.time()

    def skipped_on_page():  # a reading browser skips too: newest-only events coalesce between its reads
        return int(browser.find_element(By.TAG_NAME, "body").get_attribute("data-browser-skipped") or 0)
    skipped_at_stall = skipped_on_page()
    until(lambda: skipped_on_page() > skipped_at_stall, 60, "stereo-view counts the stalled browser's skipped events")
    until(lambda: "frame" in browser.find_element(By.CSS_SELECTOR, "#disparity-figure .info").text, 5,
          "the reading page still updated")

    def heartbeat_after_stall():
        try:
            return any(t > stalled_at * 1e6 and c["browsers"].skipped > skipped_at_stall
                       for t, c in view_counters(bus, view.pid))
        except ValueError:  # the recording's last event half-written
            return False
    until(heartbeat_after_stall, 30, "a stereo-view heartbeat after the stall")
    stalled.close()
    bus.stop()

    stats = [s for s in bus.events("CLOUD_STATS") if str(s.frame_id) == shown["frame"]]
    assert stats, "no CLOUD_STATS of frame " + shown["frame"]
    assert int(shown["points"]) == stats[0].stage_points[-1]
    assert float(shown["offset"]) == stats[0].plane_offset
    disparity = bus.events("STEREO_DISPARITY")[0]
    assert float(shown["f"]) == disparity.f and float(shown["baseline"]) == disparity.baseline
    ticks = [(float(d), float(m)) for d, m in shown["ticks"]]
    assert ticks[0][0] == max(1.0, disparity.min_disparity)
    assert ticks[-1][0] == disparity.min_disparity + disparity.num_disparities
    for d, metres in ticks:
        assert metres == pytest.approx(disparity.f * disparity.baseline / d, rel=1e-12)

    heartbeats = view_counters(bus, view.pid)
    before = [c for t, c in heartbeats if t <= stalled_at * 1e6]
    assert before and heartbeats[-1][0] > stalled_at * 1e6
    images_before, images_after = before[-1]["STEREO_IMAGES"], heartbeats[-1][1]["STEREO_IMAGES"]
    assert heartbeats[-1][1]["browsers"].skipped > before[-1]["browsers"].skipped
    captured = [(s.utime, {c.channel: c for c in s.channels}) for s in bus.events("PROCESS_STATUS")
                if s.name == "stereo-capture"]
    sent = [c["STEREO_IMAGES"].published for t, c in captured]
    received = images_after.received - images_before.received
    window = heartbeats[-1][0] - [t for t, c in heartbeats if t <= stalled_at * 1e6][-1]
    # The capture's rate over the same window, from its own heartbeats.
    rate = (sent[-1] - sent[0]) / ((captured[-1][0] - captured[0][0]) * 1e-6)
    assert received >= 0.8 * rate * window * 1e-6, (received, rate, window)
    assert images_after.dropped == images_before.dropped


def shown(driver, selector):
    return driver.find_element(By.CSS_SELECTOR, selector).is_displayed()


@pytest.mark.recorded("PROCESS_STATUS")
def test_stale_a_source_that_stops_is_named_and_the_page_is_no_longer_live(bus, browser):
    capture = bus.start("stereo-capture", ["--source", "sim:config/sim/wall.yaml", "--rate", "3", "--loop"])
    port = free_port()
    recording = os.path.join(bus.folder, "launch.lcmlog")  # as the launcher passes its recording
    view = bus.start("stereo-view", ["--port", str(port), "--calib", CALIBRATION, "--first-view", "depth",
                                     "--recording", recording, "--recording-cap-mb", "0.001"])
    browser.get(bus.page(port, view))

    # The page opens on the launch's view; what it has not got explains itself.
    until(lambda: "active" in attribute(browser, "#tab-depth", "class"), 30, "the depth tab, as --first-view says")
    until(lambda: attribute(browser, "#connection", "data-state") == "live", 60, "live once images flow")
    until(lambda: attribute(browser, "#rect-right .age", "data-age-s"), 60, "the rectified pair's age")
    assert float(attribute(browser, "#rect-right .age", "data-age-s")) < 3
    assert shown(browser, "#disparity-figure .empty") and not shown(browser, "#disparity"), \
        "without stereo-match the disparity panel says why, and shows no broken image"
    assert "stereo-match" in browser.find_element(By.CSS_SELECTOR, "#disparity-figure .empty").text
    assert shown(browser, "#cloud-figure .empty")
    assert "stereo-health publishes" in browser.find_element(By.CSS_SELECTOR, "#health-age + .waiting").text
    # No banner while images flow (a loaded machine may starve the simulator for 3 s: then it is due).
    until(lambda: not shown(browser, "#stale"), 20, "no stale banner while images flow")
    screenshot(browser, bus, "depth-without-match.png")

    # The source stops (SIGTERM: it exits 0): the banner names it, the page is not live, ages grow.
    capture.send_signal(signal.SIGTERM)
    assert capture.wait(timeout=20) == 0
    stopped_at = time.time()
    until(lambda: "STEREO_IMAGES" in (attribute(browser, "#stale", "data-channels") or ""), 30,
          "the banner names STEREO_IMAGES as stale")
    banner = browser.find_element(By.ID, "stale").text
    assert "stereo-capture" in banner and "since" in banner, banner
    assert attribute(browser, "#connection", "data-state") == "stale"
    assert browser.find_element(By.ID, "connection").text != "live"
    until(lambda: float(attribute(browser, "#rect-right .age", "data-age-s")) >= 3, 10, "the images' age grows")
    assert "old" in attribute(browser, "#rect-right .age", "class")
    # Its last heartbeat says how it ended: stopped, not done.
    until(lambda: [s for s in bus.events("PROCESS_STATUS") if s.name == "stereo-capture" and s.state == "stopped"],
          10, "stereo-capture's last heartbeat says stopped")
    row = until(lambda: browser.find_elements(By.CSS_SELECTOR, "#processes tbody.ended[data-state=stopped]"), 10,
                "the process table shows stereo-capture stopped")[0]
    assert row.get_attribute("data-process").startswith("stereo-capture")
    assert row.find_element(By.CSS_SELECTOR, ".state").text == "stopped"  # whole, not cut to 14 characters
    until(lambda: "no STEREO_IMAGES from stereo-capture (stopped) since" in browser.find_element(By.ID, "stale").text,
          10, "the banner says how its sender ended")
    assert time.time() - stopped_at < 60
    screenshot(browser, bus, "stale.png")

    # The recording: its size against the cap, then that it stopped, on the page and in stereo-view's heartbeat.
    with open(recording, "wb") as f:
        f.write(b"x" * 500)
    until(lambda: "recording 0 of 0.001 MB" in browser.find_element(By.ID, "recording").text, 10, "the recording's size")
    assert attribute(browser, "#stale", "data-recording-capped") == "false"
    with open(recording, "ab") as f:
        f.write(b"x" * 1000)
    until(lambda: attribute(browser, "#stale", "data-recording-capped") == "true", 10, "the cap reached, on the page")
    assert "Recording stopped: " + recording + " reached its cap of 0.001 MB" in browser.find_element(By.ID, "stale").text
    assert "recording stopped" in browser.find_element(By.ID, "recording").text
    # In its last error, and in its state (stereo-status's STATE), which a later error does not replace.
    until(lambda: [s for s in bus.events("PROCESS_STATUS") if s.name == "stereo-view" and s.state == "recording stopped" and
                   s.last_error.startswith("recording stopped: " + recording + " reached its cap")], 10,
          "stereo-view's heartbeat says the recording stopped (stereo-status shows it)")
