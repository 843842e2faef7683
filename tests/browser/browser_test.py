#!/usr/bin/env python3
"""lancer's pages in a real headless browser (Debian's chromium, driven by
Debian's python3-selenium through chromium-driver):

- `lancer live`: the page loads, shows the coarse image then the refined
  one, shows a located error after a broken save and drops it after the fix;
- `lancer render --preview`: the image refines pass by pass while the
  progress moves, and the stats line shows when the render is done;
- `lancer trade`'s report: it renders, every plot and image loads.

No page may log a console error. Usage: browser_test.py PATH/TO/lancer
"""
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By

LANCER = None

SCENE = """camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.8, 0.2, 0.2> rgb 0.9 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.4, 1> } }
"""
# Line 4, column 27: a second radius where POV-Ray wants a pigment.
BROKEN = SCENE.replace("0.6 pigment", "0.6 0.6 pigment")


def start_browser():
    try:
        socket.getaddrinfo("localhost", None)
    except OSError:
        raise AssertionError("'localhost' does not resolve, and chromedriver needs it to reach the browser: "
                             "add '127.0.0.1 localhost' to /etc/hosts (scripts/setup-deps.sh does)")
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     "--allow-file-access-from-files", "--window-size=1200,900"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver_path = shutil.which("chromedriver") or "/usr/bin/chromedriver"
    return webdriver.Chrome(service=Service(driver_path), options=options)


def wait_until(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError("timed out after %g s waiting for %s" % (seconds, what))


class Lancer:
    """A lancer process in the background whose page address is read off
    its stderr."""

    def __init__(self, arguments, folder):
        self.log_path = os.path.join(folder, "lancer-%d.log" % len(os.listdir(folder)))
        self.log = open(self.log_path, "w")
        self.process = subprocess.Popen([LANCER] + arguments, cwd=folder, stdout=self.log,
                                        stderr=subprocess.STDOUT)
        self.url = wait_until(self._url, 30, "lancer to print its page's address")

    def _url(self):
        with open(self.log_path) as text:
            found = re.search(r"http://127\.0\.0\.1:\d+/", text.read())
        if not found and self.process.poll() is not None:
            raise AssertionError("lancer exited: " + self.output())
        return found.group(0) if found else None

    def output(self):
        with open(self.log_path) as text:
            return text.read()

    def stop(self):
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
        status = self.process.wait(timeout=30)
        self.log.close()
        return status


class Page:
    def __init__(self, driver):
        self.driver = driver

    def data(self, name):
        return self.driver.find_element(By.TAG_NAME, "body").get_attribute("data-" + name)

    def text(self, element_id):
        return self.driver.find_element(By.ID, element_id).text

    def image_width(self):
        return self.driver.execute_script(
            "const i = document.getElementById('image'); return i.complete ? i.naturalWidth : 0;")

    def console_errors(self):
        return [entry for entry in self.driver.get_log("browser") if entry["level"] == "SEVERE"]


class BrowserTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="lancer-browser-")
        self.driver = start_browser()
        self.page = Page(self.driver)

    def tearDown(self):
        self.driver.quit()
        shutil.rmtree(self.folder, ignore_errors=True)

    def write_scene(self, text):
        path = os.path.join(self.folder, "scene.pov")
        # As an editor saves: a new file renamed over the old one.
        with open(path + ".tmp", "w") as scene:
            scene.write(text)
        os.replace(path + ".tmp", path)
        return path

    def assert_no_console_errors(self):
        self.assertEqual(self.page.console_errors(), [])

    def test_live_shows_renders_and_located_errors(self):
        self.write_scene(SCENE)
        lancer = Lancer(["live", "scene.pov", "-i", "path", "--spp", "16", "--width", "96", "--height", "72"],
                        self.folder)
        try:
            self.driver.get(lancer.url)
            # The coarse image, then the full one refining: several images
            # published (the page, polling, may show only the last).
            wait_until(lambda: self.page.data("state") == "done", 60, "the first render to finish")
            wait_until(lambda: int(self.page.data("images-loaded")) >= 1, 10, "the image to load")
            wait_until(lambda: self.page.image_width() == 96, 10, "the full-size image")
            self.assertGreaterEqual(int(self.page.data("image-version")), 3)
            self.assertIn("path, 96x72", self.page.text("message"))
            self.assertFalse(self.driver.find_element(By.ID, "errors").is_displayed())

            # A broken save: the error, located, appears.
            loaded = int(self.page.data("images-loaded"))
            self.write_scene(BROKEN)
            wait_until(lambda: self.page.data("state") == "error", 30, "the error to show")
            errors = self.driver.find_element(By.ID, "errors")
            self.assertTrue(errors.is_displayed())
            self.assertIn("scene.pov:4:27: error:", errors.text)

            # The fix: the error goes and a new render comes.
            self.write_scene(SCENE.replace("0.2, 0.4, 1", "1, 0.4, 0.2"))
            wait_until(lambda: self.page.data("state") == "done", 60, "the fixed scene to render")
            wait_until(lambda: int(self.page.data("images-loaded")) > loaded, 10, "a new image")
            self.assertEqual(self.page.text("errors"), "")
            self.assertFalse(self.driver.find_element(By.ID, "errors").is_displayed())
            self.assert_no_console_errors()
        finally:
            self.assertEqual(lancer.stop(), 0, lancer.output())

    def test_render_preview_refines_pass_by_pass(self):
        self.write_scene(SCENE)
        output = os.path.join(self.folder, "out.png")
        lancer = Lancer(["render", "scene.pov", "-i", "path", "--spp", "1024", "--width", "128", "--height", "96",
                         "--preview", "-o", output], self.folder)
        try:
            self.driver.get(lancer.url)
            # Images come while the render still runs, and the progress moves.
            seen_versions = set()
            seen_percents = set()

            def refined_while_rendering():
                if self.page.data("state") == "rendering":
                    seen_versions.add(self.page.data("image-version"))
                    seen_percents.add(self.page.text("percent"))
                return len(seen_versions) >= 3 and len(seen_percents) >= 2

            wait_until(refined_while_rendering, 60, "the image to refine during the render")
            wait_until(lambda: self.page.data("state") == "done", 120, "the render to finish")
            self.assertRegex(self.page.text("message"), r"128x96, 1024 spp, path")
            wait_until(lambda: self.page.image_width() == 128, 10, "the final image")
            self.assertTrue(os.path.exists(output))
            self.assert_no_console_errors()
        finally:
            self.assertEqual(lancer.stop(), 0, lancer.output())

    def test_trade_report_renders_with_its_plots(self):
        self.write_scene(SCENE)
        result = subprocess.run([LANCER, "trade", "scene.pov", "--out", "trade", "--quick", "--budget", "4",
                                 "--width", "32", "--height", "24", "--cache", "cache"], cwd=self.folder,
                                capture_output=True, text=True, timeout=300)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.driver.get("file://" + os.path.join(self.folder, "trade", "index.html"))
        self.assertIn("Verdict", self.driver.find_element(By.TAG_NAME, "h2").text)
        self.assertTrue(self.driver.find_element(By.CSS_SELECTOR, "p.recommended code").text.startswith(
            "lancer render"))
        wait_until(lambda: self.driver.execute_script(
            "return Array.from(document.images).every(i => i.complete);"), 20, "every image to load")
        broken = self.driver.execute_script(
            "return Array.from(document.images).filter(i => i.naturalWidth === 0).map(i => i.src);")
        self.assertEqual(broken, [])
        plots = self.driver.execute_script(
            "return Array.from(document.images).filter(i => i.src.endsWith('.svg')).length;")
        self.assertEqual(plots, 3)
        self.assert_no_console_errors()


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: browser_test.py PATH/TO/lancer [unittest options]")
    LANCER = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
