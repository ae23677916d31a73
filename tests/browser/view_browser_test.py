#!/usr/bin/python3
"""Browser tests of the HTML view (`massprops view`), in headless Chromium through Selenium.

Run by ctest (tests/CMakeLists.txt) with Debian's python3, python3-selenium, chromium and
chromium-driver:

    /usr/bin/python3 tests/browser/view_browser_test.py --tool build/massprops \
        --testdata testdata --shared ../shared

Without ../shared/corpus (two of the pages are corpus robots) it exits 77, which ctest reports as
skipped, or fails where ../shared is there (tests/shared_data.py).

What is checked, each against numbers worked out here, independently of the tool:
- the page loads from a file with the network switched off, asks for nothing but itself (the
  browser's network log), and logs nothing to the console;
- it draws one inertia box per link of positive mass (counted from the URDF here);
- each box's sides are those of the uniform box with the link's principal moments, computed here
  from the URDF's six numbers with numpy: s_k = sqrt(6 (I_i + I_j - I_k) / m) (the moments of a
  uniform box m/12 (b² + c²) etc., solved for the sides), and the base link of the fixture, whose
  inertia is that of its 0.3 x 0.2 x 0.1 m collision box, gets that very box;
- clicking a link in the list selects it and shows its findings in `check`'s words (the
  "severity: HEADLINE [rule]" line, the help, as `massprops check --format json` gives them; the
  full message in the headline's tooltip) with file:line, and the repair `fix --dry-run`
  describes;
- a screenshot of the 3D view is not blank and differs between two models.
"""
import argparse
import base64
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ET

import numpy as np
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import shared_data  # noqa: E402  (tests/shared_data.py)

ARGS = None

CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--no-first-run", "--disable-sync",
    "--enable-unsafe-swiftshader",  # software WebGL for this trusted local page, no deprecation notice
    "--window-size=1200,800",
]


def start_browser(user_data_dir):
    options = webdriver.ChromeOptions()
    options.binary_location = ARGS.chromium
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    options.add_argument("--user-data-dir=" + user_data_dir)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    driver = webdriver.Chrome(service=Service(ARGS.chromedriver), options=options)
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    return driver


def page_logs(driver):
    """What the page logged: the browser log without the GL driver's own performance notes
    (SwiftShader's "GPU stall due to ReadPixels" when a screenshot reads the canvas back), which
    come from the browser, not from the page."""
    return [entry for entry in driver.get_log("browser")
            if not (entry.get("source") == "rendering" and "GL Driver Message" in entry["message"])]


def urdf_links(path):
    """(name, mass, 3x3 inertia matrix as written) of every link with an <inertial>."""
    links = []
    for link in ET.parse(path).getroot().findall("link"):
        inertial = link.find("inertial")
        if inertial is None:
            continue
        mass = float(inertial.find("mass").get("value"))
        i = inertial.find("inertia")
        g = lambda k: float(i.get(k, "0"))
        # URDF writes the inertia matrix entries (ixy is the matrix entry, -∫xy dm).
        matrix = np.array([[g("ixx"), g("ixy"), g("ixz")],
                           [g("ixy"), g("iyy"), g("iyz")],
                           [g("ixz"), g("iyz"), g("izz")]])
        links.append((link.get("name"), mass, matrix))
    return links


def expected_box(mass, matrix):
    """Sides of the uniform box with the matrix's principal moments (ascending), side k along
    moment k: s_k = sqrt(6 (I_i + I_j - I_k) / m), a negative argument (no such box) giving 0.
    The principal moments do not depend on the inertial frame's rotation (eigenvalues)."""
    moments = np.linalg.eigvalsh(matrix)
    total = moments.sum()
    return [math.sqrt(max(0.0, 6 * (total - 2 * moments[k]) / mass)) for k in range(3)]


def run_tool(*args):
    return subprocess.run([ARGS.tool, *args], capture_output=True, text=True, timeout=120)


class ViewPageTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="massprops-view-test-")
        cls.fixture = os.path.join(ARGS.testdata, "view", "five_links.urdf")
        robots = os.path.join(ARGS.corpus, "example-robot-data", "robots")
        cls.clean = os.path.join(robots, "double_pendulum_description", "urdf", "double_pendulum.urdf")
        cls.errors = os.path.join(robots, "hyq_description", "robots", "hyq_no_sensors.urdf")
        # Two 1 kg links 1 m apart (boxes of 0.1 m): neither hides the other in the view.
        cls.apart = os.path.join(cls.tmp, "apart.urdf")
        with open(cls.apart, "w") as f:
            link = ('<link name="{0}"><inertial><mass value="1"/><inertia ixx="0.001" iyy="0.001" '
                    'izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>')
            f.write('<robot name="apart">' + link.format("left") + link.format("right") +
                    '<joint name="j" type="fixed"><origin xyz="0 1 0"/><parent link="left"/>'
                    '<child link="right"/></joint></robot>')
        cls.pages = {}
        for key, model in (("fixture", cls.fixture), ("clean", cls.clean), ("errors", cls.errors),
                           ("apart", cls.apart)):
            out = os.path.join(cls.tmp, key + ".html")
            result = run_tool("view", model, "-o", out, "--package-path", ARGS.corpus)
            assert result.returncode == 0, result.stderr
            cls.pages[key] = out
        cls.driver = start_browser(os.path.join(cls.tmp, "profile"))
        # Each page opened once here: its state, what it logged and asked the network for, and a
        # screenshot of its 3D view. The tests below that change the page open it again.
        cls.loaded = {}
        for key in cls.pages:
            state = cls.open_page(key)
            time.sleep(0.3)  # let the first animation frame land
            shot = cls.driver.find_element(By.ID, "view").screenshot_as_base64
            urls = []
            for entry in cls.driver.get_log("performance"):
                message = json.loads(entry["message"])["message"]
                if message["method"] == "Network.requestWillBeSent":
                    urls.append(message["params"]["request"]["url"])
            cls.loaded[key] = {"state": state, "logs": page_logs(cls.driver), "urls": urls,
                               "screenshot": shot}

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def open_page(cls, key):
        cls.driver.get_log("browser")  # drop what earlier pages logged
        cls.driver.get_log("performance")
        cls.driver.get("file://" + cls.pages[key])
        WebDriverWait(cls.driver, 60).until(
            lambda d: d.execute_script("return !!(window.massprops && window.massprops.ready)"))
        return cls.driver.execute_script("return window.massprops")

    def open(self, key):
        return self.open_page(key)

    def test_page_loads_offline_without_requests_or_console_output(self):
        for key, loaded in self.loaded.items():
            self.assertTrue(loaded["state"]["webgl"], key)
            self.assertEqual(loaded["logs"], [], f"{key}: the page logged {loaded['logs']}")
            urls = loaded["urls"]
            self.assertEqual([u for u in urls if not u.startswith(("file:", "data:"))], [], key)
            self.assertIn("file://" + self.pages[key], urls)

    def test_one_box_per_link_of_positive_mass_with_the_sides_of_its_principal_moments(self):
        for key, model in (("fixture", self.fixture), ("errors", self.errors), ("clean", self.clean)):
            state = self.loaded[key]["state"]
            expected = {name: expected_box(mass, matrix)
                        for name, mass, matrix in urdf_links(model) if mass > 0}
            self.assertEqual(sorted(l["name"] for l in state["links"]), sorted(expected), key)
            self.assertEqual(state["scene"]["boxes"], len(expected), key)
            for link in state["links"]:
                want = expected[link["name"]]
                scale = max(want)
                for got, w in zip(link["box"], want):
                    self.assertAlmostEqual(got, w, delta=1e-9 * scale + 1e-12,
                                           msg=f"{key}: {link['name']}: {link['box']} vs {want}")
        # The fixture's base: inertia of its own 0.3 x 0.2 x 0.1 m box (ascending moments: the
        # smallest moment is about the longest side).
        state = self.loaded["fixture"]["state"]
        base = next(l for l in state["links"] if l["name"] == "base")
        for got, want in zip(base["box"], [0.3, 0.2, 0.1]):
            self.assertAlmostEqual(got, want, delta=1e-12)
        # 'bad' breaks the triangle inequality: no equivalent box exists (drawn with a side 0).
        bad = next(l for l in state["links"] if l["name"] == "bad")
        self.assertFalse(bad["box_exists"])
        self.assertTrue(base["box_exists"])

    def test_clicking_a_link_in_the_list_selects_it_and_shows_its_findings_and_repair(self):
        report = json.loads(run_tool("check", "--format", "json", self.fixture).stdout)
        findings = [f for f in report["files"][0]["findings"] if f["link"] == "bad"]
        self.assertTrue(any(f["severity"] == "error" for f in findings))
        dry_run = run_tool("fix", "--dry-run", self.fixture).stdout
        repair_line = next(line for line in dry_run.splitlines() if "'bad'" in line)
        self.open("fixture")
        self.assertIsNone(self.driver.execute_script("return window.massprops.selected"))
        row = self.driver.find_element(By.CSS_SELECTOR, 'tr[data-link="bad"]')
        row.click()
        self.assertEqual(self.driver.execute_script("return window.massprops.selected"), "bad")
        self.assertIn("selected", row.get_attribute("class"))
        details = self.driver.find_element(By.ID, "details").text
        for f in findings:
            self.assertIn(f"{f['severity']}: {f['headline']} [{f['rule']}]", details)
            self.assertIn("help: " + f["help"], details)
            self.assertIn(f"{f['file']}:{f['line']}", details)
        tooltips = [node.get_attribute("title") for node in
                    self.driver.find_elements(By.CSS_SELECTOR, "#details .finding [title]")]
        for f in findings:
            self.assertIn(f["message"], tooltips)
        # The dry run prints "FILE:LINE: <description>"; the page shows the description.
        description = repair_line.split(": ", 1)[1]
        self.assertIn(description, details)
        # Another link: its own numbers, no findings of 'bad'.
        self.driver.find_element(By.CSS_SELECTOR, 'tr[data-link="base"]').click()
        self.assertEqual(self.driver.execute_script("return window.massprops.selected"), "base")
        self.assertNotIn(findings[0]["headline"], self.driver.find_element(By.ID, "details").text)

    def test_clicking_a_box_in_the_view_selects_its_link_and_the_background_deselects(self):
        self.open("apart")
        view = self.driver.find_element(By.ID, "view")
        size = view.size
        for name in ("left", "right"):
            x, y = self.driver.execute_script("return window.massprops.screenPosition(arguments[0])", name)
            # ActionChains offsets are from the element's center.
            ActionChains(self.driver).move_to_element_with_offset(
                view, int(x - size["width"] / 2), int(y - size["height"] / 2)).click().perform()
            self.assertEqual(self.driver.execute_script("return window.massprops.selected"), name)
        # A corner of the view shows no link.
        ActionChains(self.driver).move_to_element_with_offset(
            view, -size["width"] // 2 + 3, -size["height"] // 2 + 3).click().perform()
        self.assertIsNone(self.driver.execute_script("return window.massprops.selected"))

    def test_dark_system_theme_gives_a_dark_page(self):
        body = "return getComputedStyle(document.body).backgroundColor"
        self.open("fixture")
        self.assertEqual(self.driver.execute_script(body), "rgb(255, 255, 255)")  # view.css light
        self.driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {
            "features": [{"name": "prefers-color-scheme", "value": "dark"}]})
        try:
            self.open("fixture")
            self.assertEqual(self.driver.execute_script(body), "rgb(13, 17, 23)")  # #0d1117
            self.assertEqual(page_logs(self.driver), [])
        finally:
            self.driver.execute_cdp_cmd("Emulation.setEmulatedMedia", {"features": []})

    def screenshot_stats(self, first, second):
        """Decodes two PNG screenshots in the browser: per image the number of distinct colours
        (4 bits per channel) and the fraction of pixels unlike the corner pixel (the background);
        and the fraction of pixels that differ between the two."""
        script = """
        var done = arguments[arguments.length - 1];
        function load(src) {
          return new Promise(function (ok) { var i = new Image(); i.onload = function () { ok(i); }; i.src = src; });
        }
        Promise.all([load(arguments[0]), load(arguments[1])]).then(function (images) {
          var pixels = images.map(function (img) {
            var c = document.createElement('canvas'); c.width = img.width; c.height = img.height;
            var g = c.getContext('2d'); g.drawImage(img, 0, 0);
            return g.getImageData(0, 0, img.width, img.height).data;
          });
          var stats = pixels.map(function (p) {
            var colours = {}, unlike = 0;
            for (var i = 0; i < p.length; i += 4) {
              colours[(p[i] >> 4) + ',' + (p[i + 1] >> 4) + ',' + (p[i + 2] >> 4)] = 1;
              if (Math.abs(p[i] - p[0]) + Math.abs(p[i + 1] - p[1]) + Math.abs(p[i + 2] - p[2]) > 24) unlike++;
            }
            return {colours: Object.keys(colours).length, unlike: unlike / (p.length / 4)};
          });
          var a = pixels[0], b = pixels[1], differ = 0;
          var n = Math.min(a.length, b.length);
          for (var i = 0; i < n; i += 4) {
            if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 24) differ++;
          }
          done({first: stats[0], second: stats[1], differ: differ / (n / 4)});
        });
        """
        self.driver.set_script_timeout(30)
        return self.driver.execute_async_script(
            script, "data:image/png;base64," + first, "data:image/png;base64," + second)

    def test_screenshot_of_the_view_is_not_blank_and_differs_between_two_models(self):
        stats = self.screenshot_stats(self.loaded["clean"]["screenshot"],
                                      self.loaded["errors"]["screenshot"])
        for which in ("first", "second"):
            self.assertGreater(stats[which]["colours"], 20, stats)
            self.assertGreater(stats[which]["unlike"], 0.02, stats)
        self.assertGreater(stats["differ"], 0.02, stats)

    def test_ellipsoid_toggle_and_selection_by_api(self):
        self.open("fixture")
        self.driver.execute_script(
            "var s = document.getElementById('shape'); s.value = 'ellipsoid';"
            "s.dispatchEvent(new Event('change'));")
        self.assertEqual(self.driver.execute_script("return window.massprops.shape"), "ellipsoid")
        # Uniform solid ellipsoid: I_k = m (a_i² + a_j²) / 5, so a_k² = 5 (I_i + I_j - I_k) / (2m).
        state = self.driver.execute_script("return window.massprops")
        for name, mass, matrix in urdf_links(self.fixture):
            link = next(l for l in state["links"] if l["name"] == name)
            moments = np.linalg.eigvalsh(matrix)
            for k in range(3):
                want = math.sqrt(max(0.0, 2.5 * (moments.sum() - 2 * moments[k]) / mass))
                self.assertAlmostEqual(link["ellipsoid"][k], want, delta=1e-9 * max(link["box"]))
        self.assertTrue(self.driver.execute_script("return window.massprops.select('arm')"))
        self.assertEqual(self.driver.execute_script("return window.massprops.selected"), "arm")
        self.assertEqual(page_logs(self.driver), [])


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("--tool", required=True)
    parser.add_argument("--testdata", required=True)
    parser.add_argument("--shared", required=True, help="the shared folder (../shared)")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--chromedriver", default="/usr/bin/chromedriver")
    ARGS, rest = parser.parse_known_args()
    shared_data.check(ARGS.shared, ["corpus/example-robot-data/robots"])
    ARGS.corpus = os.path.join(ARGS.shared, "corpus")
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
