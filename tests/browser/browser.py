# tests/browser/browser.py
# Opens pages written by `hmira view` in Debian's headless Chromium through Playwright (its own
# browser download is not used), waits for the render-done flag, and returns screenshots.
# Shared by the browser tests and scripts/gallery.sh.
import os
import time
from contextlib import contextmanager

from playwright.sync_api import sync_playwright

CHROMIUM = os.environ.get("HMIRA_CHROMIUM", "/usr/bin/chromium")
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run"]


@contextmanager
def chromium():
    """A headless Chromium (the system one; raises if it is missing, so a test never skips)."""
    if not os.access(CHROMIUM, os.X_OK):
        raise RuntimeError(f"{CHROMIUM} not found: install Debian's chromium (scripts/install-deps.sh) or set HMIRA_CHROMIUM")
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
        try:
            yield browser
        finally:
            browser.close()


class Opened:
    """A page after its first frame: console messages, the time to render-done, the Playwright page."""

    def __init__(self, page, messages, seconds):
        self.page, self.messages, self.seconds = page, messages, seconds

    def screenshot(self, path=None, hide_ui=False):
        if hide_ui:
            self.page.evaluate("document.querySelectorAll('.hmira-ui').forEach(e => e.style.visibility = 'hidden')")
        return self.page.screenshot(path=path)


def open_page(browser, html_path, fragment="", size=(800, 600), timeout_s=60):
    """Navigates to the page and waits until it sets window.hmiraRenderDone."""
    page = browser.new_page(viewport={"width": size[0], "height": size[1]})
    messages = []
    page.on("console", lambda m: messages.append((m.type, m.text)))
    page.on("pageerror", lambda e: messages.append(("error", f"uncaught: {e}")))
    url = "file://" + os.path.abspath(html_path) + (("#" + fragment) if fragment else "")
    start = time.perf_counter()
    page.goto(url, wait_until="commit", timeout=timeout_s * 1000)
    page.wait_for_function("window.hmiraRenderDone === true", timeout=timeout_s * 1000, polling=20)
    return Opened(page, messages, time.perf_counter() - start)
