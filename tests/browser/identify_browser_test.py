#!/usr/bin/python3
"""Browser test of `massprops identify --html FILE` (docs/identify.md), in headless Chromium
through Selenium, with Debian's python3, python3-selenium, chromium and chromium-driver:

    /usr/bin/python3 tests/browser/identify_browser_test.py --tool build/massprops \
        --testdata testdata --chromium /usr/bin/chromium --chromedriver /usr/bin/chromedriver

The page is written for testdata/identify/planar_arm.urdf and planar_arm.csv (800 samples,
--validate 0.3: the last 240 held out). Checked, against numbers worked out here:
- the page loads from a file with the network switched off and logs nothing to the console;
- it draws one Chart.js line chart per joint of the model (2), each with the measured, identified
  and file's torques of the 240 held-out samples, the measured ones equal to the CSV's `J.tau`
  columns read here;
- the RMS of measured minus identified over the plotted samples, computed here, equals the
  report's held-out RMS (`--format json`) to 1e-9;
- every chart's canvas has drawn pixels.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

ARGS = None


def start_browser(user_data_dir):
    options = webdriver.ChromeOptions()
    options.binary_location = ARGS.chromium
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--no-first-run", "--disable-sync",
                 "--window-size=1200,800"]:
        options.add_argument(flag)
    options.add_argument("--user-data-dir=" + user_data_dir)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(ARGS.chromedriver), options=options)
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    return driver


class IdentifyHtmlTest(unittest.TestCase):
    def test_charts_show_the_held_out_torques_of_the_report(self):
        robot = os.path.join(ARGS.testdata, "identify", "planar_arm.urdf")
        data = os.path.join(ARGS.testdata, "identify", "planar_arm.csv")
        with tempfile.TemporaryDirectory() as tmp:
            page = os.path.join(tmp, "identify.html")
            report = json.loads(subprocess.run(
                [ARGS.tool, "identify", "--format", "json", "--validate", "0.3", "--html", page,
                 robot, data], check=True, capture_output=True, text=True).stdout)
            with open(data) as f:
                rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
            header, rows = rows[0], rows[1:]
            driver = start_browser(os.path.join(tmp, "profile"))
            try:
                driver.get("file://" + page)
                WebDriverWait(driver, 30).until(
                    lambda d: d.execute_script("return (window.identifyCharts || []).length") == 2)
                charts = driver.execute_script(
                    "return window.identifyCharts.map(c => ({"
                    "  labels: c.data.datasets.map(s => s.label),"
                    "  data: c.data.datasets.map(s => s.data),"
                    "  drawn: (() => { const x = c.canvas.getContext('2d').getImageData("
                    "    0, 0, c.canvas.width, c.canvas.height).data; let n = 0;"
                    "    for (let i = 3; i < x.length; i += 4) if (x[i] > 0) ++n; return n; })()"
                    "}))")
                logs = driver.get_log("browser")
            finally:
                driver.quit()
        self.assertEqual(logs, [])
        self.assertEqual([j["joint"] for j in report["joints"]], ["shoulder", "elbow"])
        for chart, joint in zip(charts, report["joints"]):
            self.assertEqual(chart["labels"], ["measured", "identified", "file's values"])
            measured, identified, _ = chart["data"]
            self.assertEqual(len(measured), 240)
            self.assertEqual(len(identified), 240)
            column = header.index(joint["joint"] + ".tau")
            expected = [float(r[column]) for r in rows[-240:]]
            for a, b in zip(measured, expected):
                self.assertAlmostEqual(a, b, delta=1e-12 * (1 + abs(b)))
            rms = math.sqrt(sum((m - i) ** 2 for m, i in zip(measured, identified)) / 240)
            self.assertAlmostEqual(rms, joint["rms_identified"], delta=1e-9 * rms)
            self.assertGreater(chart["drawn"], 1000)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    for name in ("--tool", "--testdata", "--chromium", "--chromedriver"):
        parser.add_argument(name, required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0]] + rest)
