#!/usr/bin/python3
"""One browser on stereo-view's page for the transport benchmark: Debian's
headless Chromium (Selenium) opens the page's depth view and keeps it open,
reading every update, until Ctrl-C (the launcher's stop).
    bench/transport/browser.py http://127.0.0.1:PORT/ [--log-dir DIR] [--quiet] ..."""
import signal
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By


def main():
    url = next(a for a in sys.argv[1:] if a.startswith("http"))
    options = webdriver.ChromeOptions()
    for flag in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,1200",
                 "--enable-unsafe-swiftshader", "--use-angle=swiftshader"):
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
        while not stop:
            time.sleep(0.2)
    finally:
        driver.quit()


if __name__ == "__main__":
    main()
