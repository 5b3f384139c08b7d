"""Headless Chromium through chromedriver (Debian's chromium and chromium-driver) for the browser's tests."""

from __future__ import annotations

import shutil
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"


def start(width: int = 1280, height: int = 1000, timeout: float = 90) -> webdriver.Chrome:
    """A headless Chromium with a throwaway profile; the caller quits it (which also removes the profile)."""
    for program in (CHROMIUM, CHROMEDRIVER):
        if shutil.which(program) is None:
            raise RuntimeError(f"{program} not found (install chromium and chromium-driver)")
    profile = tempfile.mkdtemp(prefix="arg-chromium-")
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new",
                 # Chromium's sandbox refuses to run as root, which make test may be.
                 "--no-sandbox",
                 # Containers often have a small /dev/shm, which crashes tabs.
                 "--disable-dev-shm-usage", "--disable-gpu", "--disable-extensions",
                 # WebGL (the 3D view) on the CPU: no GPU here, and newer Chromium wants it asked for.
                 "--enable-unsafe-swiftshader",
                 "--no-first-run", "--hide-scrollbars", "--force-device-scale-factor=1",
                 f"--window-size={width},{height}", f"--user-data-dir={profile}"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(executable_path=CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(timeout)
    # quit() stops chromedriver and Chromium; the profile goes with them.
    quit_driver = driver.quit

    def quit_and_clean() -> None:
        try:
            quit_driver()
        finally:
            shutil.rmtree(profile, ignore_errors=True)

    driver.quit = quit_and_clean  # type: ignore[method-assign]
    return driver
