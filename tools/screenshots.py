#!/usr/bin/python3
"""Screenshots and load time of the HTML view (`massprops view`) in headless Chromium.

    /usr/bin/python3 tools/screenshots.py [--tool build/massprops] [--corpus ../shared/corpus]
                                          [--out docs] [--timing]

Writes docs/view-clean.png (solo, a corpus robot without findings, its OBJ meshes drawn) and
docs/view-errors.png (hyq_no_sensors, with errors and warnings; its link rh_foot selected).
With --timing it also writes a 200-link chain whose every link has a corpus mesh (STL and OBJ,
cycled), opens its page five times and prints the file size and the load times (navigation start
to the page drawn: window.massprops.load_ms). Needs Debian's python3-selenium, chromium and
chromium-driver; the network is switched off in the browser.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def browser(profile, width, height):
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--no-first-run", "--disable-sync",
                 "--enable-unsafe-swiftshader", "--hide-scrollbars",
                 f"--window-size={width},{height}", "--user-data-dir=" + profile]:
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": 0, "uploadThroughput": 0})
    return driver


def open_page(driver, path):
    driver.get("file://" + os.path.abspath(path))
    WebDriverWait(driver, 60).until(
        lambda d: d.execute_script("return !!(window.massprops && window.massprops.ready)"))
    return driver.execute_script("return window.massprops")


def view(tool, model, out, corpus):
    subprocess.run([tool, "view", model, "-o", out, "--package-path", corpus], check=True)


def chain_with_meshes(corpus, n, path):
    """A serial chain of n links, each a 1.5 kg body with a corpus mesh as collision."""
    robots = os.path.join(corpus, "example-robot-data", "robots")
    meshes = []
    for sub in ("double_pendulum_description/meshes", "finger_edu_description/meshes",
                "solo_description/meshes/obj/with_foot"):
        folder = os.path.join(robots, sub)
        meshes += sorted(os.path.join(folder, f) for f in os.listdir(folder)
                         if f.endswith((".stl", ".obj")))
    out = ['<?xml version="1.0"?>\n<robot name="chain_with_meshes">\n']
    for k in range(n):
        mesh = os.path.abspath(meshes[k % len(meshes)])
        out.append(f'''  <link name="link{k}">
    <inertial><origin xyz="0 0 0.05"/><mass value="1.5"/>
      <inertia ixx="0.00145" ixy="0" ixz="0" iyy="0.00145" iyz="0" izz="0.0004"/></inertial>
    <collision><geometry><mesh filename="{mesh}" scale="0.5 0.5 0.5"/></geometry></collision>
  </link>\n''')
        if k > 0:
            out.append(f'''  <joint name="joint{k}" type="revolute"><origin xyz="0 0 0.1" rpy="0 0.05 0"/>
    <parent link="link{k - 1}"/><child link="link{k}"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n''')
    out.append("</robot>\n")
    with open(path, "w") as f:
        f.write("".join(out))
    return len(set(meshes[k % len(meshes)] for k in range(n)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tool", default=os.path.join(REPO, "build", "massprops"))
    parser.add_argument("--corpus", default=os.path.join(REPO, "..", "shared", "corpus"))
    parser.add_argument("--out", default=os.path.join(REPO, "docs"))
    parser.add_argument("--timing", action="store_true")
    args = parser.parse_args()
    robots = os.path.join(args.corpus, "example-robot-data", "robots")
    tmp = tempfile.mkdtemp(prefix="massprops-screenshots-")

    driver = browser(os.path.join(tmp, "profile"), 1100, 640)
    try:
        shots = [("view-clean.png", os.path.join(robots, "solo_description", "robots", "solo.urdf"), None),
                 ("view-errors.png", os.path.join(robots, "hyq_description", "robots",
                                                  "hyq_no_sensors.urdf"), "rh_foot")]
        for name, model, selected in shots:
            page = os.path.join(tmp, name + ".html")
            view(args.tool, model, page, args.corpus)
            open_page(driver, page)
            if selected:
                driver.execute_script("window.massprops.select(arguments[0])", selected)
            driver.execute_script("return new Promise(function (r) { requestAnimationFrame(function () { requestAnimationFrame(r); }); })")
            out = os.path.join(args.out, name)
            driver.save_screenshot(out)
            print(f"{out}: {os.path.getsize(out)} bytes")

        if args.timing:
            model = os.path.join(tmp, "chain200.urdf")
            distinct = chain_with_meshes(args.corpus, 200, model)
            page = os.path.join(tmp, "chain200.html")
            view(args.tool, model, page, args.corpus)
            times = []
            for _ in range(5):
                state = open_page(driver, page)
                times.append(state["load_ms"])
            print(f"200-link chain, {distinct} distinct meshes: page {os.path.getsize(page)} bytes, "
                  f"{len(state['links'])} boxes, {state['scene']['meshes']} meshes drawn; load "
                  f"(navigation start to drawn) median {statistics.median(times):.0f} ms, "
                  f"max {max(times):.0f} ms over {len(times)} loads")
    finally:
        driver.quit()


if __name__ == "__main__":
    sys.exit(main())
