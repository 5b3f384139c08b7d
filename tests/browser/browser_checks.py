"""The catalogue browser's checks in headless Chromium, against a running browser and its database; prints TAP."""

from __future__ import annotations

import argparse
import io
import re
import sys
import tempfile
import urllib.error
import urllib.request
import uuid
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple

import psycopg
from PIL import Image, ImageStat
from selenium.common.exceptions import WebDriverException
from selenium.webdriver.common.by import By
from selenium.webdriver.remote.webdriver import WebDriver
from selenium.webdriver.remote.webelement import WebElement
from selenium.webdriver.support import expected_conditions as EC
from selenium.webdriver.support.ui import Select, WebDriverWait

import chrome
import tap
from tap import expect

# Seconds to wait for a page or an image: generous, as the machine may be busy building.
WAIT = 60
# A mesh the server cannot read: an OFF header that promises more vertices than follow.
BAD_MESH = b"OFF\n4 2 0\n0 0 0\n1 0 0\n"


class Browser:
    """The checks, sharing one Chromium, the browser's URL and the catalogue as the database has it."""

    def __init__(self, url: str, models: Path, screenshot: Path) -> None:
        self.url = url.rstrip("/") + "/"
        self.models_dir = models
        self.screenshot = screenshot
        self.driver: Optional[WebDriver] = None
        with psycopg.connect() as conn:
            self.models: List[Dict[str, Any]] = [
                dict(zip(("id", "model_id", "title", "class", "file"), row)) for row in conn.execute(
                    "SELECT id, model_id, title, class, file FROM objects ORDER BY id")]

    # --- helpers ------------------------------------------------------------------------------

    @property
    def d(self) -> WebDriver:
        assert self.driver is not None
        return self.driver

    def wait(self, condition: Any) -> Any:
        return WebDriverWait(self.d, WAIT).until(condition)

    def open(self, path: str, ready: str) -> None:
        """Loads a page and waits for the element (CSS selector) that says it is there."""
        self.d.get(self.url + path)
        self.wait(EC.presence_of_element_located((By.CSS_SELECTOR, ready)))

    def click_to(self, element: WebElement, ready: str) -> None:
        """Clicks a link or button and waits for the next page's element (CSS selector)."""
        old = self.d.find_element(By.TAG_NAME, "html")
        element.click()
        self.wait(EC.staleness_of(old))
        self.wait(EC.presence_of_element_located((By.CSS_SELECTOR, ready)))

    def images_loaded(self, selector: str) -> int:
        """Waits until every image matching the selector is done loading; returns how many loaded
        (a broken image is done but has no width)."""
        script = ("const all = Array.from(document.querySelectorAll(arguments[0]));"
                  "return all.every(i => i.complete) ? all.filter(i => i.naturalWidth > 0).length : null;")

        def done(driver: WebDriver) -> Optional[Tuple[int]]:
            loaded = driver.execute_script(script, selector)
            return None if loaded is None else (loaded,)  # a tuple: "done" even when 0 loaded

        return self.wait(done)[0]

    def card_ids(self) -> List[str]:
        return [c.get_attribute("data-model-id") for c in self.d.find_elements(By.CSS_SELECTOR, "#grid .card")]

    def ranked_rows(self) -> List[Tuple[str, float, str]]:
        """(model_id, sim, the SIM cell's text) of each row of a ranking page."""
        rows = self.d.find_elements(By.CSS_SELECTOR, "#ranked tr.result")
        return [(r.get_attribute("data-model-id"), float(r.get_attribute("data-sim")),
                 r.find_element(By.CSS_SELECTOR, "td.sim").text) for r in rows]

    def ids_of_class(self, cls: str) -> List[str]:
        return sorted(m["model_id"] for m in self.models if m["class"] == cls)

    def expect_query_first(self, model: Dict[str, Any]) -> List[Tuple[str, float, str]]:
        rows = self.ranked_rows()
        expect(len(rows) > 0, "the ranking is empty")
        first_id, first_sim, first_text = rows[0]
        expect(first_id == model["model_id"],
               f"first row is {first_id}, not the query {model['model_id']} (rows: {rows[:3]})")
        expect(first_sim == 0.0 and first_text == "0.0000",
               f"the query's SIM is {first_sim!r} (shown {first_text!r}), not 0")
        return rows

    def http(self, method: str, path: str, body: Optional[bytes] = None,
             headers: Optional[Dict[str, str]] = None) -> Tuple[int, str, str]:
        """(status, content type, body) of one request outside Chromium, whatever the status."""
        request = urllib.request.Request(self.url + path, data=body, method=method, headers=headers or {})
        try:
            with urllib.request.urlopen(request, timeout=WAIT) as response:
                return response.status, response.headers.get("Content-Type", ""), response.read().decode()
        except urllib.error.HTTPError as error:
            return error.code, error.headers.get("Content-Type", ""), error.read().decode()

    # --- the checks ---------------------------------------------------------------------------

    def grid_shows_every_model(self) -> None:
        self.open("", "#grid")
        shown = self.card_ids()
        expected = [m["model_id"] for m in self.models]
        expect(len(expected) > 0, "the catalogue is empty")
        expect(sorted(shown) == sorted(expected),
               f"{len(shown)} cards for {len(expected)} models; missing "
               f"{sorted(set(expected) - set(shown))[:5]}, extra {sorted(set(shown) - set(expected))[:5]}")

    def grid_thumbnails_load(self) -> None:
        self.open("", "#grid")
        loaded = self.images_loaded("#grid .card img")
        expect(loaded == len(self.models), f"{loaded} thumbnails loaded for {len(self.models)} models")

    def screenshot_not_blank(self) -> None:
        self.open("", "#grid")
        self.images_loaded("#grid .card img")
        png = self.d.get_screenshot_as_png()
        self.screenshot.write_bytes(png)
        image = Image.open(io.BytesIO(png)).convert("RGB")
        spread = ImageStat.Stat(image.convert("L")).stddev[0]
        colours = image.getcolors(maxcolors=1 << 24) or []
        expect(spread > 10 and len(colours) > 200,
               f"the screenshot ({self.screenshot}) looks blank: grey level spread {spread:.1f}, "
               f"{len(colours)} colours")

    def filter_narrows_grid(self) -> None:
        cls = self.models[-1]["class"]
        self.open("", "#grid")
        Select(self.d.find_element(By.CSS_SELECTOR, "form.filters select[name='class']")
               ).select_by_value(cls)
        self.click_to(self.d.find_element(By.CSS_SELECTOR, "form.filters button"), "#grid")
        shown = sorted(self.card_ids())
        expect(shown == self.ids_of_class(cls), f"class {cls}: the grid shows {shown}, "
               f"the table has {self.ids_of_class(cls)}")

    def object_page_shows_graph(self) -> None:
        model = self.models[0]
        self.open("", "#grid")
        self.click_to(self.d.find_element(By.CSS_SELECTOR, "#grid .card a"), "#title")
        title = self.d.find_element(By.ID, "title").text
        expect(title == model["title"], f"object page titled {title!r}, not {model['title']!r}")
        expect(self.images_loaded("#graph") == 1, "the Reeb graph picture did not load")
        status, kind, svg = self.http("GET", f"object/{model['id']}/graph.svg?level=2")
        expect(status == 200 and kind.startswith("image/svg+xml") and "<svg" in svg,
               f"graph.svg: HTTP {status}, {kind}, starts {svg[:60]!r}")

    def more_like_this_lists_query_first(self) -> None:
        # A card in the middle of the grid, so that "first" says something.
        model = self.models[len(self.models) // 2]
        self.open("", "#grid")
        card = self.d.find_element(By.CSS_SELECTOR, f"#grid .card[data-model-id='{model['model_id']}']")
        self.click_to(card.find_element(By.CSS_SELECTOR, "a.more-like-this"), "#ranked")
        self.expect_query_first(model)

    def ranking_is_ordered(self) -> None:
        model = self.models[1]
        self.open(f"object/{model['id']}/similar?k=all", "#ranked")
        rows = self.expect_query_first(model)
        sims = [sim for _, sim, _ in rows]
        expect(len(rows) == len(self.models), f"k=all shows {len(rows)} of {len(self.models)} models")
        expect(sims == sorted(sims) and all(0 <= s <= 1 for s in sims), f"SIMs not ascending in [0, 1]: {sims}")

    def more_like_this_filtered(self) -> None:
        # Chromium's inspector now and then loses a node while the page is being replaced
        # ("Node with given id does not belong to the document"): a lookup that raced the
        # navigation is tried again from a fresh page; a wrong ranking is never retried.
        for attempt in range(3):
            try:
                return self.more_like_this_filtered_once()
            except WebDriverException:
                if attempt == 2:
                    raise

    def more_like_this_filtered_once(self) -> None:
        model = self.models[-1]
        self.open(f"object/{model['id']}", "#title")
        Select(self.d.find_element(By.CSS_SELECTOR, "form.filters select[name='class']")
               ).select_by_value(model["class"])
        self.click_to(self.d.find_element(By.CSS_SELECTOR, "button.more-like-this"), "#ranked")
        rows = self.expect_query_first(model)
        shown = sorted(r[0] for r in rows)
        expect(shown == self.ids_of_class(model["class"]),
               f"class {model['class']}: ranked {shown}, the table has {self.ids_of_class(model['class'])}")

    def upload_finds_itself(self) -> None:
        model = self.models[len(self.models) // 3]
        # The table keeps the file's name; the file is where the catalogue was generated.
        path = (self.models_dir / model["file"]).resolve()
        expect(path.is_file(), f"the model's file {path} is gone")
        self.open("upload", "#mesh")
        self.d.find_element(By.ID, "mesh").send_keys(str(path))
        self.click_to(self.d.find_element(By.CSS_SELECTOR, "#upload button"), "#ranked")
        self.expect_query_first(model)

    def server_message(self) -> Tuple[str, str]:
        """What the database itself says of BAD_MESH: (SQLSTATE, message)."""
        with psycopg.connect() as conn:
            try:
                conn.execute("SELECT arg_build(%b)", (BAD_MESH,))
            except psycopg.Error as error:
                return error.sqlstate or "", error.diag.message_primary or ""
        raise tap.Failed("the server built an ARG of the bad mesh")

    def bad_upload_shows_server_message(self) -> None:
        sqlstate, message = self.server_message()
        with tempfile.TemporaryDirectory() as scratch:
            bad = Path(scratch) / "broken.off"
            bad.write_bytes(BAD_MESH)
            self.open("upload", "#mesh")
            self.d.find_element(By.ID, "mesh").send_keys(str(bad))
            self.click_to(self.d.find_element(By.CSS_SELECTOR, "#upload button"), "#error")
        shown = self.d.find_element(By.ID, "error").text
        state = self.d.find_element(By.ID, "sqlstate").text
        expect(shown == f"broken.off: {message}", f"the page says {shown!r}; the server said {message!r}")
        expect(state == sqlstate, f"the page shows SQLSTATE {state!r}, the server said {sqlstate!r}")
        expect("Traceback" not in self.d.page_source, "the page shows a traceback")

    def bad_upload_is_4xx(self) -> None:
        sqlstate, message = self.server_message()
        boundary = uuid.uuid4().hex
        body = (f"--{boundary}\r\nContent-Disposition: form-data; name=\"mesh\"; filename=\"broken.off\"\r\n"
                f"Content-Type: application/octet-stream\r\n\r\n").encode() + BAD_MESH + \
            f"\r\n--{boundary}--\r\n".encode()
        status, _, page = self.http("POST", "upload", body,
                                    {"Content-Type": f"multipart/form-data; boundary={boundary}"})
        expect(400 <= status < 500, f"HTTP {status} for a bad mesh, not 4xx")
        expect(sqlstate in page and "Traceback" not in page,
               f"HTTP {status}: the page lacks SQLSTATE {sqlstate} or shows a traceback")

    def unknown_object_is_404(self) -> None:
        status, _, page = self.http("GET", "object/999999")
        expect(status == 404 and "no model 999999" in page and "Traceback" not in page,
               f"HTTP {status} for an unknown object: {re.sub(r'<[^>]+>', ' ', page)[:200]!r}")

    def listens_on_localhost_only(self) -> None:
        port = int(re.search(r":(\d+)/", self.url).group(1))  # type: ignore[union-attr]
        addresses = []
        for table in ("/proc/net/tcp", "/proc/net/tcp6"):
            for line in Path(table).read_text().splitlines()[1:]:
                local, state = line.split()[1], line.split()[3]
                if state == "0A" and int(local.rsplit(":", 1)[1], 16) == port:
                    addresses.append(local.rsplit(":", 1)[0])
        expect(addresses == ["0100007F"], f"port {port} listens on {addresses} (hex), not 127.0.0.1 alone")

    def checks(self) -> List[tap.Check]:
        return [
            ("the grid shows every model of the catalogue", self.grid_shows_every_model),
            ("every model's thumbnail (from the table) loads in the grid", self.grid_thumbnails_load),
            ("a screenshot of the grid is not blank", self.screenshot_not_blank),
            ("a class filter shows that class's models and no other", self.filter_narrows_grid),
            ("an object page shows its title and its Reeb graph (arg_svg)", self.object_page_shows_graph),
            ("a click on \"more like this\" lists the query first with SIM 0", self.more_like_this_lists_query_first),
            ("\"more like this\" of every model is ordered by SIM in [0, 1]", self.ranking_is_ordered),
            ("\"more like this\" filtered by class lists that class, the query first", self.more_like_this_filtered),
            ("an upload of a known model finds itself first with SIM 0", self.upload_finds_itself),
            ("a bad upload shows the server's message and SQLSTATE, no traceback", self.bad_upload_shows_server_message),
            ("a bad upload is answered with HTTP 4xx", self.bad_upload_is_4xx),
            ("an unknown object is a 404 page", self.unknown_object_is_404),
            ("the browser listens on 127.0.0.1 only", self.listens_on_localhost_only),
        ]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--url", required=True, help="the running browser, http://127.0.0.1:PORT/")
    parser.add_argument("--models", type=Path, required=True, help="the folder of the catalogue's mesh files")
    parser.add_argument("--first", type=int, default=1, help="the number of the first TAP line")
    parser.add_argument("--screenshot", type=Path, required=True, help="where to keep the grid's screenshot")
    args = parser.parse_args()
    browser = Browser(args.url, args.models, args.screenshot)
    checks = browser.checks()
    try:
        browser.driver = chrome.start()
    except Exception as error:
        return 1 if tap.run(checks, args.first, cannot_run=f"Chromium did not start: {error}") else 0
    try:
        failed = tap.run(checks, args.first)
    finally:
        browser.driver.quit()
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
