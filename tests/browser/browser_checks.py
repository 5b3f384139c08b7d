"""The catalogue browser's checks in headless Chromium, against a running browser and its database; prints TAP."""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import re
import sys
import tempfile
import time
import urllib.error
import urllib.request
import uuid
import zipfile
from pathlib import Path
from typing import Any, Dict, Iterator, List, Optional, Tuple

import psycopg
from PIL import Image, ImageStat
from selenium.common.exceptions import WebDriverException
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.remote.webdriver import WebDriver
from selenium.webdriver.remote.webelement import WebElement
from selenium.webdriver.support import expected_conditions as EC
from selenium.webdriver.support.ui import Select, WebDriverWait

import chrome
import tap
import textured_glb
from tap import expect

# The browser's own modules, for a check of what they hand argtool (tools/browser, with the
# Python client it imports, as serve.py puts them on the path).
ROOT = Path(__file__).resolve().parents[2]
sys.path[:0] = [str(ROOT / "tools" / "browser"), str(ROOT / "clients" / "python")]
import catalogue  # noqa: E402
import pair_picture  # noqa: E402
import viewdata  # noqa: E402

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

    def upload(self, path: "Path | List[Path]", ready: str) -> None:
        """Sends a file from the upload page and waits for the answer's element (CSS selector).
        Tried up to three times on an error of the driver itself: on a loaded machine Chromium
        has answered "node does not belong to the document" for the file input it had just found
        (the page swapped under the driver); a page that is wrong fails the checks after it."""
        for attempt in range(3):
            try:
                self.open("upload", "#mesh")
                # Several files at once: their paths, one a line (a multiple file input).
                paths = path if isinstance(path, list) else [path]
                self.d.find_element(By.ID, "mesh").send_keys("\n".join(str(p) for p in paths))
                self.click_to(self.d.find_element(By.CSS_SELECTOR, "#upload button"), ready)
                return
            except WebDriverException:
                if attempt == 2:
                    raise

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

    def view_ready(self, model: Dict[str, Any], query: str = "") -> WebElement:
        """Opens an object page and waits for its 3D view to be drawn; fails with the page's message."""
        self.open(f"object/{model['id']}{query}", "#view3d")
        self.wait(lambda d: d.find_element(By.ID, "view3d").get_attribute("data-state") != "loading")
        box = self.d.find_element(By.ID, "view3d")
        if box.get_attribute("data-state") != "ready":
            raise tap.Failed(f"the 3D view of {model['model_id']} did not draw: "
                             f"{self.d.find_element(By.ID, 'view-message').text!r}")
        return box.find_element(By.TAG_NAME, "canvas")

    @staticmethod
    def picture(element: WebElement) -> Image.Image:
        return Image.open(io.BytesIO(element.screenshot_as_png)).convert("RGB")

    @staticmethod
    def changed(before: Image.Image, after: Image.Image) -> float:
        """The share of pixels that differ between two pictures of one size."""
        diff = [a != b for a, b in zip(before.getdata(), after.getdata())]
        return sum(diff) / max(len(diff), 1)

    def redraw(self, element: WebElement, before: Image.Image, what: str) -> Image.Image:
        """Waits (a few frames) until the canvas differs from `before`; fails naming `what`."""
        deadline = time.monotonic() + 10
        while True:
            after = self.picture(element)
            share = self.changed(before, after)
            if share > 0.01:
                return after
            if time.monotonic() > deadline:
                raise tap.Failed(f"{what}: {share:.2%} of the 3D view's pixels changed")
            time.sleep(0.1)

    def nodes_at(self, model: Dict[str, Any], level: int) -> int:
        with psycopg.connect() as conn:
            row = conn.execute("SELECT count(*) FROM objects o, arg_nodes(o.descr) n "
                               "WHERE o.id = %s AND n.level = %s", (model["id"], level)).fetchone()
        return int(row[0]) if row else 0

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
        self.upload(path, "#ranked")
        self.expect_query_first(model)

    def upload_shows_itself_in_3d(self) -> None:
        model = self.models[len(self.models) // 3]
        self.upload((self.models_dir / model["file"]).resolve(), "#ranked")
        self.wait(lambda d: d.find_element(By.ID, "view3d").get_attribute("data-state") != "loading")
        box = self.d.find_element(By.ID, "view3d")
        expect(box.get_attribute("data-state") == "ready",
               f"the upload's 3D view did not draw: {self.d.find_element(By.ID, 'view-message').text!r}")
        canvas = box.find_element(By.TAG_NAME, "canvas")
        before = self.picture(canvas)
        grey = ImageStat.Stat(before.convert("L"))
        expect(grey.stddev[0] > 10, f"the upload's 3D view looks blank: grey level spread {grey.stddev[0]:.1f}")
        # Its levels come with its view: as many as the catalogue's copy of the same model has.
        levels = [o.text for o in Select(self.d.find_element(By.ID, "view-level")).options]
        with psycopg.connect() as conn:
            count = conn.execute("SELECT count(DISTINCT level) FROM objects o, arg_nodes(o.descr) n "
                                 "WHERE o.id = %s", (model["id"],)).fetchone()
        expect(count is not None and levels == [str(l) for l in range(count[0])],
               f"the upload's view offers levels {levels}; the model has {count}")
        ActionChains(self.d).move_to_element(canvas).click_and_hold().move_by_offset(90, 40) \
            .release().perform()
        self.redraw(canvas, before, "after a drag on the upload's view")

    @staticmethod
    def mass_height(picture: Image.Image) -> Tuple[float, int]:
        """Where the centre of mass of a picture's non-white pixels lies, as a share of their height
        from the top (0 at the top, 1 at the bottom), and how many pixels there are. A standing
        figure carries its torso, arms and head above thin legs: upright, it is under 0.5."""
        grey = picture.convert("L")
        rows = [i // grey.width for i, v in enumerate(grey.getdata()) if v < 250]
        if not rows:
            return 0.5, 0
        top, bottom = min(rows), max(rows)
        return (sum(rows) / len(rows) - top) / max(bottom - top, 1), len(rows)

    def figures(self) -> List[Dict[str, Any]]:
        figures = [m for m in self.models if m["class"] == "human"]
        expect(len(figures) > 0, "the sample has no standing figure")
        return figures

    def thumbnail_stands_upright(self) -> None:
        for model in self.figures():
            with urllib.request.urlopen(self.url + f"thumbnail/{model['id']}.png", timeout=WAIT) as response:
                share, pixels = self.mass_height(Image.open(io.BytesIO(response.read())))
            expect(pixels > 100, f"{model['model_id']}'s thumbnail is blank")
            expect(share < 0.5, f"{model['model_id']} stands on its head in its thumbnail: its centre "
                   f"of mass is at {share:.2f} of its height from the top")

    def catalogue_up_stands_animals(self) -> None:
        # The sample's catalogue says +z is up (argtool gen); the load keeps it and the thumbnails
        # follow it. Without it, the side the shape stands on lays the first one on its back.
        with psycopg.connect() as conn:
            ups = {r[0] for r in conn.execute("SELECT DISTINCT up FROM objects")}
        expect(ups == {"+z"}, f"the table keeps the catalogue's up as {sorted(map(str, ups))}, not +z")
        animals = [m for m in self.models if m["class"] == "fourleg"]
        expect(len(animals) > 0, "the sample has no four-legged animal")
        for model in animals:
            with urllib.request.urlopen(self.url + f"thumbnail/{model['id']}.png", timeout=WAIT) as response:
                share, pixels = self.mass_height(Image.open(io.BytesIO(response.read())))
            expect(pixels > 100, f"{model['model_id']}'s thumbnail is blank")
            expect(share < 0.5, f"{model['model_id']} lies on its back in its thumbnail: its centre of "
                   f"mass is at {share:.2f} of its height from the top")

    def view_starts_upright(self) -> None:
        model = self.figures()[0]
        share, pixels = self.mass_height(self.picture(self.view_ready(model)))
        expect(pixels > 100, f"the 3D view of {model['model_id']} is blank")
        expect(share < 0.5, f"{model['model_id']} stands on its head in the 3D view: its centre of mass "
               f"is at {share:.2f} of its height from the top")

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
            self.upload(bad, "#error")
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

    def view_renders_and_turns(self) -> None:
        model = self.models[0]
        canvas = self.view_ready(model)
        before = self.picture(canvas)
        grey = ImageStat.Stat(before.convert("L"))
        colours = before.getcolors(maxcolors=1 << 24) or []
        expect(grey.stddev[0] > 10 and len(colours) > 50,
               f"the 3D view looks blank: grey level spread {grey.stddev[0]:.1f}, {len(colours)} colours")
        ActionChains(self.d).move_to_element(canvas).click_and_hold().move_by_offset(90, 40) \
            .release().perform()
        self.redraw(canvas, before, "after a drag")

    def view_graph_toggle(self) -> None:
        model = self.models[0]
        canvas = self.view_ready(model)
        box = self.d.find_element(By.ID, "view3d")
        level = int(Select(self.d.find_element(By.ID, "view-level")).first_selected_option.text)
        plain = self.picture(canvas)
        self.d.find_element(By.ID, "view-graph").click()
        expected = self.nodes_at(model, level)
        shown = box.get_attribute("data-nodes")
        expect(expected > 0 and shown == str(expected),
               f"the graph shows {shown} nodes at level {level}; the ARG has {expected}")
        with_graph = self.redraw(canvas, plain, "after showing the graph")
        Select(self.d.find_element(By.ID, "view-colour")).select_by_value("mu")
        expect(box.get_attribute("data-mode") == "mu", "the surface is not coloured by mu")
        self.redraw(canvas, with_graph, "after colouring by mu")
        Select(self.d.find_element(By.ID, "view-level")).select_by_value("1")
        fewer = self.nodes_at(model, 1)
        expect(box.get_attribute("data-nodes") == str(fewer),
               f"level 1: the graph shows {box.get_attribute('data-nodes')} nodes, the ARG has {fewer}")

    def pair_terms_sum_to_sim(self) -> None:
        model = self.models[len(self.models) // 2]
        self.open(f"object/{model['id']}/similar", "#ranked")
        second = self.d.find_elements(By.CSS_SELECTOR, "#ranked tr.result")[1]
        ranked_sim = float(second.get_attribute("data-sim"))
        self.click_to(second.find_element(By.CSS_SELECTOR, "a.why"), "#terms")
        shown = self.d.find_element(By.ID, "pair-sim")
        sim = float(shown.get_attribute("data-sim"))
        terms = self.d.find_elements(By.CSS_SELECTOR, "#terms tr.term")
        names = [t.get_attribute("data-term") for t in terms]
        expect(names == ["graph", "panorama", "spectrum"], f"the terms shown are {names}")
        total = 0.0
        for t in terms:  # added in the order shown, as SIM adds them
            total += float(t.get_attribute("data-contribution"))
        expect(total == sim, f"the terms add up to {total!r}, the SIM shown is {sim!r}")
        expect(sim == ranked_sim, f"the pair's SIM {sim!r} is not the ranking's {ranked_sim!r}")
        expect(shown.text == f"{sim:.6f}", f"the SIM reads {shown.text!r}")
        weights = [float(t.get_attribute("data-weight")) for t in terms]
        expect(weights[0] > 0 and all(w >= 0 for w in weights), f"weights {weights}")
        features = self.d.find_elements(By.CSS_SELECTOR, "#features tr.feature")
        expect(len(features) == 6, f"{len(features)} features of the graph shown, not 6")
        expect(self.images_loaded("#pair-picture") == 1, "the picture of the matched nodes did not load")

    def presets_change_the_order(self) -> None:
        model = self.models[len(self.models) // 2]
        rankings = {}
        for look in ("shape", "shape-colour", "colour"):
            self.open(f"object/{model['id']}/similar?k=all&look={look}", "#ranked")
            chosen = Select(self.d.find_element(By.ID, "look")).first_selected_option.get_attribute("value")
            expect(chosen == look, f"the page's appearance is {chosen}, not {look}")
            rankings[look] = self.expect_query_first(model)
            sims = [r[1] for r in rankings[look]]
            expect(sims == sorted(sims), f"{look}: SIMs not ascending")
        orders = {look: [r[0] for r in rows] for look, rows in rankings.items()}
        expect(orders["shape"] != orders["colour"] or orders["shape"] != orders["shape-colour"],
               f"the three appearances rank alike: {orders['shape'][:6]}")
        # Each SIM shown is the server's under that preset.
        second, shown, _ = rankings["colour"][1]
        with psycopg.connect() as conn:
            sim = conn.execute("SELECT arg_sim(a.descr, b.descr, 'colour') FROM objects a, objects b "
                               "WHERE a.model_id = %s AND b.model_id = %s", (second, model["model_id"])).fetchone()
        expect(sim is not None and shown == sim[0], f"colour: SIM shown {shown!r}, the server's {sim}")

    def part_click_finds_parts(self) -> None:
        model = self.models[0]
        canvas = self.view_ready(model)
        ActionChains(self.d).move_to_element(canvas).click().perform()
        box = self.d.find_element(By.ID, "view3d")
        picked = int(box.get_attribute("data-picked"))
        expect(picked >= 0, "a click in the middle of the 3D view picked no node")
        # Node 1's disc, found by its colour (viewer.js's second node colour), picks node 1.
        before = self.picture(canvas)
        self.d.find_element(By.ID, "view-graph").click()
        shot = self.redraw(canvas, before, "after showing the graph")
        width, height = shot.size
        disc = [(x, y) for y in range(0, height, 2) for x in range(0, width, 2)
                if sum(abs(a - b) for a, b in zip(shot.getpixel((x, y)), (255, 127, 14))) < 20]
        expect(len(disc) > 10, f"node 1's disc not found in the 3D view ({len(disc)} pixels)")
        x, y = sum(p[0] for p in disc) // len(disc), sum(p[1] for p in disc) // len(disc)
        ActionChains(self.d).move_to_element_with_offset(canvas, x - width // 2, y - height // 2) \
            .click().perform()
        expect(box.get_attribute("data-picked") == "1",
               f"a click on node 1's disc picked node {box.get_attribute('data-picked')}")
        link = self.d.find_element(By.ID, "part-link")
        expect(link.is_displayed(), "no link to search by the picked part")
        self.click_to(link, "#parts")
        rows = self.d.find_elements(By.CSS_SELECTOR, "#parts tr.result")
        expect(len(rows) > 0, "no model has a part like the one picked")
        scores = [float(r.get_attribute("data-score")) for r in rows]
        expect(scores == sorted(scores) and all(0 <= x <= 1 for x in scores), f"scores {scores}")
        expect(self.images_loaded("#parts img.part-graph") == len(rows), "a part's graph did not load")
        first = rows[0]
        src = first.find_element(By.CSS_SELECTOR, "img.part-graph").get_attribute("src")
        status, _, svg = self.http("GET", src.split("/", 3)[3])
        expect(status == 200 and svg.count('class="marked"') == 1,
               f"the first result's graph does not ring its part (HTTP {status})")

    def bad_view_input_is_clear(self) -> None:
        status, kind, body = self.http("GET", "object/999999/view.json")
        expect(status == 404 and kind.startswith("application/json") and
               "no model 999999" in json.loads(body).get("error", ""),
               f"view.json of an unknown object: HTTP {status} {body[:120]!r}")
        model = self.models[0]
        status, _, page = self.http("GET", f"object/{model['id']}/part?level=2&node=9999")
        expect(status == 404 and "has no node 9999 at level 2" in page and "Traceback" not in page,
               f"an unknown node: HTTP {status}: {re.sub(r'<[^>]+>', ' ', page)[:200]!r}")
        status, _, page = self.http("GET", f"pair/{model['id']}/999999")
        expect(status == 404 and "no model 999999" in page, f"a pair with an unknown object: HTTP {status}")
        # The largest model, over the limit run_browser_tests.sh sets: too large to display.
        with psycopg.connect() as conn:
            large = conn.execute("SELECT id, (arg_info(descr)->>'triangles')::int FROM objects "
                                 "ORDER BY 2 DESC, id LIMIT 1").fetchone()
        assert large is not None
        self.open(f"object/{large[0]}", "#title")
        self.wait(lambda d: d.find_element(By.ID, "view-message").is_displayed())
        text = self.d.find_element(By.ID, "view-message").text
        expect(f"too large to display in 3D: {large[1]:,} triangles" in text,
               f"a model too large to display: the page says {text!r}")
        # An object without a mesh: its page says so where the view would be.
        with psycopg.connect(autocommit=True) as conn:
            conn.execute("INSERT INTO objects (id, model_id, title) VALUES (999998, 'no-mesh', 'No mesh')")
            try:
                self.open("object/999998", "#title")
                self.wait(lambda d: d.find_element(By.ID, "view-message").is_displayed())
                text = self.d.find_element(By.ID, "view-message").text
                expect("has no mesh" in text and "Traceback" not in self.d.page_source,
                       f"an object without a mesh: the page says {text!r}")
            finally:
                conn.execute("DELETE FROM objects WHERE id = 999998")

    @staticmethod
    def checker_pixels(picture: Image.Image) -> Tuple[int, int]:
        """How many pixels have the hue of the checkerboard's magenta, and of its green, shaded."""
        magenta = green = 0
        for r, g, b in picture.getdata():
            if r > 60 and b > 60 and g < 0.35 * min(r, b):
                magenta += 1
            elif g > 60 and r < 0.4 * g and b < 0.4 * g:
                green += 1
        return magenta, green

    def texture_mapped(self, what: str) -> WebElement:
        """Waits for the 3D view on the page and its texture; its canvas (fails if not mapped)."""
        self.wait(lambda d: d.find_element(By.ID, "view3d").get_attribute("data-state") != "loading")
        box = self.d.find_element(By.ID, "view3d")
        expect(box.get_attribute("data-state") == "ready",
               f"{what}: the 3D view did not draw: {self.d.find_element(By.ID, 'view-message').text!r}")
        self.wait(lambda d: box.get_attribute("data-texture") != "loading")
        expect(box.get_attribute("data-texture") == "mapped",
               f"{what}: the texture is {box.get_attribute('data-texture')!r}, not mapped "
               f"({self.d.find_element(By.ID, 'view-note').text!r})")
        return box.find_element(By.TAG_NAME, "canvas")

    @contextlib.contextmanager
    def object_for_one_check(self, object_id: int, model_id: str, title: str, file: str,
                             mesh: bytes) -> Iterator[None]:
        """A catalogue object put in for one check only (the others count the sample's models and
        classes), its page open on the 3D view; taken out again whatever the check found."""
        with psycopg.connect(autocommit=True) as conn:
            conn.execute("INSERT INTO objects (id, model_id, title, class, file, mesh) "
                         "VALUES (%s, %s, %s, 'globe', %s, %s)", (object_id, model_id, title, file, mesh))
            try:
                self.open(f"object/{object_id}", "#view3d")
                yield
            finally:
                conn.execute("DELETE FROM objects WHERE id = %s", (object_id,))

    def view_maps_a_texture(self) -> None:
        glb = textured_glb.globe_glb()
        with self.object_for_one_check(999997, "textured-globe", "Textured globe", "globe.glb", glb):
            canvas = self.texture_mapped("a textured GLB")
            shot = self.picture(canvas)
            magenta, green = self.checker_pixels(shot)
            expect(magenta > 500 and green > 500,
                   f"the checkerboard's colours in the 3D view: {magenta} magenta, {green} green pixels")
            Select(self.d.find_element(By.ID, "view-colour")).select_by_value("mu")
            mu = self.redraw(canvas, shot, "after colouring the textured object by mu")
            expect(self.checker_pixels(mu)[0] < 50, "mu colouring still shows the texture's magenta")
            ActionChains(self.d).move_to_element(canvas).click().perform()
            picked = int(self.d.find_element(By.ID, "view3d").get_attribute("data-picked"))
            expect(picked >= 0, "a click on the textured surface picked no node")
            with urllib.request.urlopen(self.url + "object/999997/texture/0", timeout=WAIT) as answer:
                kind, image = answer.headers.get("Content-Type", ""), answer.read()
            expect(kind == "image/png" and image == textured_glb.checker_png(),
                   f"the texture route sends {kind} of {len(image)} bytes, not the GLB's PNG")
        with tempfile.TemporaryDirectory() as scratch:
            path = Path(scratch) / "globe.glb"
            path.write_bytes(glb)
            self.upload(path, "#ranked")
            magenta, green = self.checker_pixels(self.picture(self.texture_mapped("an uploaded textured GLB")))
            expect(magenta > 500 and green > 500,
                   f"the upload's 3D view: {magenta} magenta, {green} green pixels")

    @staticmethod
    def blue_pixels(picture: Image.Image) -> int:
        """How many pixels have the hue of two_textures_glb's south, shaded (blue, not mu's cyan)."""
        return sum(1 for r, g, b in picture.getdata() if b > 60 and r < 0.35 * b and g < 0.5 * b)

    def view_maps_each_primitives_texture(self) -> None:
        glb = textured_glb.two_textures_glb()
        with self.object_for_one_check(999996, "two-textures", "Two textures", "two.glb", glb):
            shot = self.picture(self.texture_mapped("a GLB of two textures"))
            magenta, green = self.checker_pixels(shot)
            blue = self.blue_pixels(shot)
            # The colours baked from a texture look like it too: the view says how many of its
            # materials draw their texture.
            maps = self.d.find_element(By.ID, "view3d").get_attribute("data-maps")
            expect(maps == "2" and magenta > 300 and green > 300 and blue > 300,
                   f"each primitive's texture, the south's times its factor: {maps} textures drawn, "
                   f"{magenta} magenta, {green} green, {blue} blue pixels")
            view = json.loads(urllib.request.urlopen(self.url + "object/999996/view.json", timeout=WAIT).read())
            factors = [t["factor"] for t in view["textures"]]
            expect(len(view["images"]) == 2 and factors == [[1, 1, 1], [0.1, 0.2, 1]],
                   f"view.json lists {len(view['images'])} images, factors {factors}")
            with urllib.request.urlopen(self.url + "object/999996/texture/1", timeout=WAIT) as answer:
                second = answer.read()
            expect(second == textured_glb.south_png(),
                   f"texture/1 sends {len(second)} bytes, not the GLB's second PNG")
            status, _, page = self.http("GET", "object/999996/texture/2")
            expect(status == 404 and "no texture image 2" in page, f"texture/2: HTTP {status}: {page[:200]!r}")

    def upload_obj_with_mtl_and_texture(self) -> None:
        obj, mtl = textured_glb.globe_obj()
        with tempfile.TemporaryDirectory() as scratch:
            folder = Path(scratch)
            (folder / "model.obj").write_text(obj)
            (folder / "model.mtl").write_text(mtl)
            (folder / "checker.png").write_bytes(textured_glb.checker_png())
            self.upload([folder / "model.obj", folder / "model.mtl", folder / "checker.png"], "#ranked")
            shot = self.picture(self.texture_mapped("an OBJ uploaded with its MTL and texture"))
            magenta, green = self.checker_pixels(shot)
            expect(magenta > 500 and green > 500,
                   f"the uploaded OBJ's 3D view: {magenta} magenta, {green} green pixels")
            note = self.d.find_element(By.ID, "upload-texture").text
            expect("checker.png" in note, f"the page says {note!r} of the texture")
        # The same as a zip, and a zip that is not one: a 4xx page saying why, no traceback.
        archive = io.BytesIO()
        with zipfile.ZipFile(archive, "w") as z:
            z.writestr("globe/model.obj", obj)
            z.writestr("globe/model.mtl", mtl)
            z.writestr("globe/textures/checker.png", textured_glb.checker_png())
        for name, data, want in (("globe.zip", archive.getvalue(), 200), ("broken.zip", b"PK\3\4 cut", 400)):
            boundary = uuid.uuid4().hex
            body = (f"--{boundary}\r\nContent-Disposition: form-data; name=\"mesh\"; filename=\"{name}\"\r\n"
                    f"Content-Type: application/zip\r\n\r\n").encode() + data + f"\r\n--{boundary}--\r\n".encode()
            status, _, page = self.http("POST", "upload", body,
                                        {"Content-Type": f"multipart/form-data; boundary={boundary}"})
            expect(status == want and "Traceback" not in page,
                   f"{name}: HTTP {status}, not {want}: {re.sub(r'<[^>]+>', ' ', page)[:300]!r}")
            if want == 200:
                expect("Shown with its texture checker.png" in page, f"{name}: the page does not name its texture")
                key = re.search(r'/upload/([0-9a-f]+)/view\.json', page)
                expect(key is not None, f"{name}: no 3D view on the page")
                assert key is not None
                with urllib.request.urlopen(self.url + f"upload/{key.group(1)}/texture/0", timeout=WAIT) as answer:
                    expect(answer.read() == textured_glb.checker_png(), f"{name}: the texture route sends another image")
            else:
                expect("broken.zip is not a zip that can be read" in page, f"{name}: the page does not say why")

    def views_follow_the_stored_options(self) -> None:
        # The demo's table builds every value with the defaults; another catalogue may not. What
        # the browser hands view-data and render-match is the stored value's own options.
        model = self.models[0]
        with catalogue.connect() as conn:
            row = catalogue.stored_mesh(conn, model["id"])
            stored = conn.execute("SELECT arg_info(descr)->>'options' FROM objects WHERE id = %s",
                                  (model["id"],)).fetchone()
        assert row is not None and stored is not None
        expect(row["options"] == stored[0] and "levels=5" in row["options"],
               f"stored_mesh's options {row['options']!r}, the value's {stored[0]!r}")
        other = row["options"].replace("levels=5", "levels=3")
        levels = {}
        for options in (row["options"], other):
            shown = viewdata.convert(model["id"], row["file"], row["mesh"], row["triangles"], row["texture"],
                                     options)
            levels[options] = len(json.loads(shown.data)["levels"])
        expect(levels == {row["options"]: 6, other: 4},
               f"levels of the 3D view's graph by the options it was given: {levels}")
        # render-match draws the level asked for only if the graphs were built with its options.
        a = (model["id"], row["file"], row["mesh"])
        try:
            pair_picture.render(a, a, "shape", 4, other)
            drew = True
        except viewdata.ViewUnavailable:
            drew = False
        expect(not drew, "render-match drew level 4 of graphs built with levels=3")
        expect(pair_picture.render(a, a, "shape", 2, other).startswith(b"\x89PNG"),
               "render-match did not draw level 2 of graphs built with levels=3")

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
            ("an upload is shown in 3D beside its ranking, with its levels, and turns", self.upload_shows_itself_in_3d),
            ("a standing figure's thumbnail stands upright (its mass above the middle)", self.thumbnail_stands_upright),
            ("a bad upload shows the server's message and SQLSTATE, no traceback", self.bad_upload_shows_server_message),
            ("a bad upload is answered with HTTP 4xx", self.bad_upload_is_4xx),
            ("an unknown object is a 404 page", self.unknown_object_is_404),
            ("the 3D view draws the object and turns when dragged", self.view_renders_and_turns),
            ("the 3D view starts with a standing figure upright, as its thumbnail", self.view_starts_upright),
            ("the catalogue's up reaches the table and the thumbnails: animals stand on their legs",
             self.catalogue_up_stands_animals),
            ("the 3D view's graph toggle shows the level's nodes, mu colours the surface", self.view_graph_toggle),
            ("a pair page shows SIM's terms with their weights, adding up to the SIM shown", self.pair_terms_sum_to_sim),
            ("shape only, shape and colour, colour first: the order changes", self.presets_change_the_order),
            ("a click on the surface or a node's disc picks a node; its part search rings each match",
             self.part_click_finds_parts),
            ("an unknown object, node or pair, no mesh or too many triangles: a clear message",
             self.bad_view_input_is_clear),
            ("a textured GLB's 3D view maps its texture, uploaded too; mu replaces it, a click picks",
             self.view_maps_a_texture),
            ("a GLB's primitives each map their own texture, times their baseColorFactor",
             self.view_maps_each_primitives_texture),
            ("an OBJ uploaded with its MTL and texture (files or a zip) is shown textured; a bad zip is a 4xx",
             self.upload_obj_with_mtl_and_texture),
            ("the 3D view and the pair picture build graphs with the stored value's options",
             self.views_follow_the_stored_options),
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
