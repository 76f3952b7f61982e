"""serve_browser.py LAMINA SRCDIR - `lamina serve`'s page in a real browser
(issue 35 item 1): headless Chromium (Debian's chromium and chromium-driver,
driven by python3-selenium) loads the page, sees a frame image update,
changes a parameter through the page's own control, and the script's next
frame and record show the new value. Exit 77 (skipped) when Chromium, its
driver or Selenium is missing."""
import os
import shutil
import signal
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from serve_lib import Server, check, finish, wait_until  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from png_text import png_texts  # noqa: E402

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    print("skipped: python3-selenium is not installed")
    sys.exit(77)
DRIVER = shutil.which("chromedriver") or "/usr/bin/chromedriver"
BROWSER = shutil.which("chromium") or "/usr/bin/chromium"
if not (os.path.exists(DRIVER) and os.path.exists(BROWSER)):
    print("skipped: chromium and chromium-driver are not installed")
    sys.exit(77)

LAMINA, SRC = sys.argv[1], sys.argv[2]
W = os.path.join(os.getcwd(), "serve_browser")
s = Server(LAMINA, os.path.join(SRC, "serve_scene.lua"), W,
           "--set", "t_end=100000", "--set", "every=0.05", "--quiet")

opts = webdriver.ChromeOptions()
opts.binary_location = BROWSER
for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
          "--no-first-run", "--user-data-dir=" + os.path.join(W, "chromium-profile")):
    opts.add_argument(a)
driver = webdriver.Chrome(service=Service(DRIVER), options=opts)
driver.set_page_load_timeout(60)
try:
    driver.get("http://127.0.0.1:%d/" % s.port)
    check("lamina serve" in driver.title, "the page loads (title %r)" % driver.title)

    def loaded_count():
        """the frame count of the image the browser has shown, 0 before"""
        imgs = driver.find_elements(By.CSS_SELECTOR, "#frames figure img")
        if not imgs:
            return 0
        ok = driver.execute_script("return arguments[0].complete && arguments[0].naturalWidth > 0",
                                   imgs[0])
        return int(imgs[0].get_attribute("data-loaded") or 0) if ok else 0

    first = wait_until(loaded_count, 60, 0.2)
    check(first > 0, "a frame image is shown (frame %d)" % first)
    later = wait_until(lambda: (lambda n: n if n > first else 0)(loaded_count()), 60, 0.2)
    check(later > first, "the image updates as frames are written (%d -> %d)" % (first, later))
    st = wait_until(lambda: driver.find_element(By.ID, "step").text not in ("", "-"), 30)
    check(st, "progress shown: step %s, t %s" % (driver.find_element(By.ID, "step").text,
                                                 driver.find_element(By.ID, "t").text))

    # the page's own control: type into amp's field, press Set
    row = wait_until(lambda: driver.find_elements(By.CSS_SELECTOR, 'tr.param[data-name="amp"]'), 30)
    check(bool(row), "the page lists the parameter amp")
    if row:
        field = row[0].find_element(By.CSS_SELECTOR, "input.value")
        field.clear()
        field.send_keys("4.5")
        row[0].find_element(By.CSS_SELECTOR, "button.set").click()
        shown = wait_until(lambda: row[0].find_element(By.CSS_SELECTOR, ".current").text == "4.5", 60, 0.2)
        check(shown, "the page shows amp = 4.5 as the script read it")
        frames_then = s.json("/api/state")["frames"][0]["count"]
        # the script's next record and frame after the change carry it
        seen = wait_until(lambda: 4.5 in s.column("amp"), 60, 0.2)
        check(seen, "the script's record shows amp = 4.5")
        plotted = wait_until(lambda: driver.find_elements(
            By.CSS_SELECTOR, 'canvas[data-column="amp"][data-last="4.5"]'), 60, 0.2)
        check(bool(plotted), "the page's plot of amp reaches 4.5")
        nxt = wait_until(lambda: (lambda n: n if n > frames_then else 0)(loaded_count()), 60, 0.2)
        check(nxt > frames_then, "a frame drawn after the change is shown (%d)" % nxt)
        check("param.amp = 4.5 (from the page)" in s.stderr(), "the run log has the change")
    # pause from the page
    driver.find_element(By.ID, "pause").click()
    paused = wait_until(lambda: driver.find_element(By.ID, "status").text == "paused", 30, 0.2)
    check(paused, "the Pause button pauses the run (status %r)" % driver.find_element(By.ID, "status").text)
    driver.find_element(By.ID, "resume").click()
    check(wait_until(lambda: driver.find_element(By.ID, "status").text == "running", 30, 0.2),
          "Resume runs it again")
finally:
    driver.quit()
s.proc.send_signal(signal.SIGTERM)
check(s.wait() == 143, "SIGTERM ends the server (143)")
with open(os.path.join(W, "out", "amp.csv")) as f:
    check("4.5" in f.read().splitlines()[-1].split(",")[-1], "amp.csv ends with amp = 4.5")


# the script's last frame (drawn after the change) says so in its own title
frames = sorted(f for f in os.listdir(os.path.join(W, "out")) if f.startswith("f") and f.endswith(".png"))
check(bool(frames), "the scene wrote frames")
title = png_texts(os.path.join(W, "out", frames[-1])).get("Title", "")
check(title == "amp = 4.5", "the last frame's title reads amp = 4.5 (%r)" % title)
finish()
