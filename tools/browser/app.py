"""The catalogue browser's web pages (FastAPI): the grid, an object in 3D, "more like this", a pair, search by upload."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional

import psycopg
from fastapi import FastAPI, Request
from fastapi.middleware.gzip import GZipMiddleware
from fastapi.responses import FileResponse, HTMLResponse, JSONResponse, PlainTextResponse, Response
from fastapi.templating import Jinja2Templates
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import UploadFile

import catalogue
import errors
import pair_picture
import pgarg
import upload_files
import viewdata

HERE = Path(__file__).resolve().parent
templates = Jinja2Templates(directory=str(HERE / "templates"))

# Rows a ranking shows unless the reader picks another number; "all" is the whole catalogue.
DEFAULT_K = 20
K_CHOICES = ["10", "20", "50", "all"]
# An upload larger than this is refused before it reaches the server (arg_build has caps too).
MAX_UPLOAD_BYTES = 64 * 1024 * 1024

app = FastAPI(title="arg catalogue browser", docs_url=None, redoc_url=None, openapi_url=None)
errors.install(app, templates)
# The 3D view's JSON is mostly digits: compressed it is a quarter of its size.
app.add_middleware(GZipMiddleware, minimum_size=4096)


def page(request: Request, name: str, status_code: int = 200, **values: Any) -> HTMLResponse:
    return templates.TemplateResponse(name, {"request": request, **values}, status_code=status_code)


def rows_wanted(value: str, total: int) -> int:
    """The k a form asks for: a number from 1 up, or "all"; anything else is the default."""
    if value == "all":
        return max(total, 1)
    try:
        return max(1, min(int(value), max(total, 1)))
    except ValueError:
        return DEFAULT_K


def model_with_mesh(conn: psycopg.Connection[Any], model_id: int, without: str) -> Dict[str, Any]:
    """The catalogue's row of a model that has a mesh; NotFound otherwise (WITHOUT ends the
    message for a model without one: what cannot be done)."""
    row = catalogue.model(conn, model_id)
    if row is None:
        raise errors.NotFound(f"there is no model {model_id} in the catalogue")
    if row["descr"] is None:
        raise errors.NotFound(f"model {model_id} has no mesh, so {without}")
    return row


def ranking_form(conn: psycopg.Connection[Any], params: Mapping[str, str]) -> Dict[str, Any]:
    """The filters and k of a ranking request, with the choices the form offers."""
    total = catalogue.count(conn)
    k_text = params.get("k") or str(DEFAULT_K)
    return {"filters": catalogue.chosen_filters(params), "choices": catalogue.filter_choices(conn),
            "k": rows_wanted(k_text, total), "k_text": k_text, "k_choices": K_CHOICES,
            "total": total}


@app.get("/healthz", response_class=PlainTextResponse)
def healthz() -> str:
    with catalogue.connect() as conn:
        return f"ok: {catalogue.count(conn)} models\n"


@app.get("/favicon.ico")
def favicon() -> Response:
    return Response(status_code=204)  # none: say so rather than log a 404 per page


@app.get("/style.css")
def style() -> FileResponse:
    return FileResponse(HERE / "static" / "style.css", media_type="text/css")


# The browser's own scripts, and three.js as npm installed it (tools/browser/install_js.sh): only
# these files, by name, so that no path from a request reaches the file system.
THREE = HERE / "node_modules" / "three"
SCRIPTS = {
    "viewer.js": HERE / "static" / "viewer.js",
    "three/three.module.min.js": THREE / "build" / "three.module.min.js",
    "three/three.core.min.js": THREE / "build" / "three.core.min.js",
    "three/addons/controls/OrbitControls.js": THREE / "examples" / "jsm" / "controls" / "OrbitControls.js",
}


def three_installed() -> bool:
    return all(path.is_file() for path in SCRIPTS.values())


@app.get("/js/{name:path}")
def script(name: str) -> FileResponse:
    path = SCRIPTS.get(name)
    if path is None or not path.is_file():
        raise errors.NotFound(f"no script {name}" + ("" if three_installed() else
                                                   " (three.js is not installed: run make deps)"))
    return FileResponse(path, media_type="text/javascript", headers={"Cache-Control": "max-age=3600"})


@app.get("/", response_class=HTMLResponse)
def grid(request: Request) -> HTMLResponse:
    params = dict(request.query_params)
    with catalogue.connect() as conn:
        filters = catalogue.chosen_filters(params)
        return page(request, "grid.html", models=catalogue.models(conn, filters), filters=filters,
                    choices=catalogue.filter_choices(conn), total=catalogue.count(conn))


@app.get("/thumbnail/{model_id}.png")
def thumbnail(model_id: int, view: str = "colours") -> Response:
    with catalogue.connect() as conn:
        png = catalogue.thumbnail(conn, model_id, mu=view == "mu")
    if png is None:
        raise errors.NotFound(f"model {model_id} has no thumbnail")
    return Response(png, media_type="image/png", headers={"Cache-Control": "max-age=3600"})


@app.get("/object/{model_id}", response_class=HTMLResponse)
def object_page(request: Request, model_id: int, level: int = 2, part: int = -1) -> HTMLResponse:
    with catalogue.connect() as conn:
        row = catalogue.model(conn, model_id)
        if row is None:
            raise errors.NotFound(f"there is no model {model_id} in the catalogue")
        levels = row["levels"] or 0  # none: no mesh, so no ARG
        level = max(0, min(level, levels - 1))
        return page(request, "object.html", model=row, level=level, levels=range(levels),
                    choices=catalogue.filter_choices(conn), three=three_installed(),
                    looks=catalogue.APPEARANCE_LABELS, look=catalogue.DEFAULT_APPEARANCE, part=part)


def model_view(model_id: int) -> viewdata.View:
    with catalogue.connect() as conn:
        row = catalogue.stored_mesh(conn, model_id)
    if row is None:
        raise viewdata.ViewUnavailable(f"there is no model {model_id} in the catalogue", 404)
    return viewdata.convert(model_id, row["file"], row["mesh"], row["triangles"], row["texture"],
                            row["options"], row["up"], row["materials"])


def unavailable(why: viewdata.ViewUnavailable) -> JSONResponse:
    """Why there is no view (or no texture), as the page's script reads it: {"error": ...}."""
    return JSONResponse({"error": why.message}, status_code=why.status_code)


async def stored_view(model_id: int) -> "viewdata.View | JSONResponse":
    """A catalogue object's 3D view, or the reason there is none."""
    try:
        return await run_in_threadpool(model_view, model_id)
    except viewdata.ViewUnavailable as why:
        return unavailable(why)


@app.get("/object/{model_id}/view.json")
async def view(model_id: int) -> Response:
    """The 3D view's data (argtool view-data); a reason as {"error": ...} when there is none."""
    shown = await stored_view(model_id)
    if isinstance(shown, Response):
        return shown
    return Response(shown.data, media_type="application/json", headers={"Cache-Control": "max-age=3600"})


def texture_response(shown: viewdata.View, what: str, index: int) -> Response:
    try:
        image, media_type = viewdata.texture_of(shown, what, index)
    except viewdata.ViewUnavailable as why:
        return unavailable(why)
    return Response(image, media_type=media_type, headers={
        "Cache-Control": "max-age=3600", "X-Content-Type-Options": "nosniff"})


@app.get("/object/{model_id}/texture")
@app.get("/object/{model_id}/texture/{index}")
async def texture(model_id: int, index: int = 0) -> Response:
    """Image INDEX of the textures the 3D view maps (PNG or JPEG, in view.json's "images");
    a reason as {"error": ...} when there is none."""
    shown = await stored_view(model_id)
    if isinstance(shown, Response):
        return shown
    return texture_response(shown, f"model {model_id}", index)


@app.get("/object/{model_id}/graph.svg")
def graph(model_id: int, level: int = 2, mark: int = -1) -> Response:
    with catalogue.connect() as conn:
        svg = catalogue.graph_svg(conn, model_id, level)
    if svg is None:
        raise errors.NotFound(f"there is no model {model_id} in the catalogue")
    if mark >= 0:
        # A matching part, ringed: arg_svg titles each node's disc "level L node N: ...".
        svg = svg.replace(f'"><title>level {level} node {mark}: ',
                          f'" stroke="#d00" stroke-width="4" class="marked"><title>level {level} node {mark}: ', 1)
    # arg_svg has no scripts or references; the policy says so to the browser as well.
    return Response(svg, media_type="image/svg+xml",
                    headers={"Content-Security-Policy": "default-src 'none'; style-src 'unsafe-inline'"})


@app.get("/object/{model_id}/similar", response_class=HTMLResponse)
def similar(request: Request, model_id: int) -> HTMLResponse:
    with catalogue.connect() as conn:
        query = model_with_mesh(conn, model_id, "nothing to rank by")
        params = dict(request.query_params)
        form = ranking_form(conn, params)
        look = catalogue.appearance(params.get("look"))
        rows = catalogue.ranked_with(conn, query["descr"], form["k"], form["filters"], look)
        return page(request, "ranked.html", query=query, rows=rows, action=f"/object/{model_id}/similar",
                    look=look, looks=catalogue.APPEARANCE_LABELS, **form)


def pair_rows(conn: psycopg.Connection[Any], a_id: int, b_id: int) -> "tuple[Dict[str, Any], Dict[str, Any]]":
    return (model_with_mesh(conn, a_id, "nothing to compare"),
            model_with_mesh(conn, b_id, "nothing to compare"))


@app.get("/pair/{a_id}/{b_id}", response_class=HTMLResponse)
def pair(request: Request, a_id: int, b_id: int, look: str = catalogue.DEFAULT_APPEARANCE,
         level: int = 2) -> HTMLResponse:
    """Why two objects are close: both side by side, matched nodes linked, SIM term by term."""
    look = catalogue.appearance(look)
    weights = catalogue.APPEARANCE[look]
    with catalogue.connect() as conn:
        a, b = pair_rows(conn, a_id, b_id)
        levels = min(a["levels"], b["levels"])
        level = max(0, min(level, levels - 1))
        sim, terms = catalogue.sim_terms(conn, a["descr"], b["descr"], weights)
        matches = catalogue.best_matches(conn, a["descr"], b["descr"], weights, level)
        return page(request, "pair.html", a=a, b=b, sim=sim, terms=terms, weights=weights, look=look,
                    looks=catalogue.APPEARANCE_LABELS, level=level, levels=range(levels), matches=matches)


def pair_png(a_id: int, b_id: int, weights: str, level: int) -> bytes:
    with catalogue.connect() as conn:
        a, b = catalogue.stored_mesh(conn, a_id), catalogue.stored_mesh(conn, b_id)
    for model_id, row in ((a_id, a), (b_id, b)):
        if row is None:
            raise viewdata.ViewUnavailable(f"there is no model {model_id} in the catalogue", 404)
        if row["mesh"] is None:
            raise viewdata.ViewUnavailable(f"model {model_id} has no mesh stored", 404)
    assert a is not None and b is not None
    # Two values are compared only when built with the same options, so a's are both's.
    return pair_picture.render((a_id, a["file"], a["mesh"]), (b_id, b["file"], b["mesh"]), weights, level,
                               a["options"])


@app.get("/pair/{a_id}/{b_id}/matches.png")
async def pair_picture_png(a_id: int, b_id: int, look: str = catalogue.DEFAULT_APPEARANCE,
                           level: int = 2) -> Response:
    weights = catalogue.APPEARANCE[catalogue.appearance(look)]
    try:
        png = await run_in_threadpool(pair_png, a_id, b_id, weights, level)
    except viewdata.ViewUnavailable as why:
        raise errors.PageError(why.message, status_code=why.status_code) from None
    return Response(png, media_type="image/png", headers={"Cache-Control": "max-age=3600"})


@app.get("/object/{model_id}/part", response_class=HTMLResponse)
def part(request: Request, model_id: int, level: int, node: int) -> HTMLResponse:
    """Search by a part: the models with a part like one node of this one (arg_part_match)."""
    with catalogue.connect() as conn:
        query = model_with_mesh(conn, model_id, "no parts")
        count = catalogue.node_count(conn, model_id, level)
        if not count or not 0 <= node < count:
            where = f"level {level} has nodes 0 to {count - 1}" if count else \
                f"its levels are 0 to {query['levels'] - 1}"
            raise errors.NotFound(f"model {model_id} has no node {node} at level {level}: {where}")
        form = ranking_form(conn, dict(request.query_params))
        rows = catalogue.part_matches(conn, model_id, level, node, form["k"])
        return page(request, "part.html", query=query, level=level, node=node, rows=rows, **form)


@app.get("/upload", response_class=HTMLResponse)
def upload_form(request: Request) -> HTMLResponse:
    with catalogue.connect() as conn:
        return page(request, "upload.html", **ranking_form(conn, {}))


# How the server begins an error that is its texture's, not its mesh's (core/io/decode_image).
IMAGE_ERROR = "cannot build ARG: image: "


def rank_upload(data: bytes, texture: Optional[bytes], params: Dict[str, str],
                notes: List[str]) -> "tuple[Dict[str, Any], List[Dict[str, Any]]]":
    """The upload's ARG built by the server (the bytes as a bind parameter; an OBJ's colours from
    its texture, as the demo builds the catalogue's), then the ranking. A texture the server
    cannot read is left out, with its reason in NOTES, as the demo's loader leaves it out."""
    with catalogue.connect() as conn:
        form = ranking_form(conn, params)
        query = None
        if texture is not None:
            try:
                query = pgarg.build(conn, data, texture=texture)
            except (psycopg.errors.DataError, psycopg.errors.ProgramLimitExceeded) as error:
                # The image's fault (one that does not decode, or over a cap: 22xxx or 54000)
                # leaves it out; the mesh's goes to the page as any refused upload does.
                message = error.diag.message_primary or str(error)
                if not message.startswith(IMAGE_ERROR):
                    raise
                notes.append(f"searched with the mesh's shape alone: the server cannot read its texture ({message})")
        if query is None:
            query = pgarg.build(conn, data)
        return form, catalogue.ranked(conn, query, form["k"], form["filters"])


async def read_upload(form_data: Any) -> upload_files.Upload:
    """The files of the form's "mesh" input, at most MAX_UPLOAD_BYTES in all, checked by
    upload_files.collect (one mesh; for an OBJ, its MTL and images; or a zip of them)."""
    given = [f for f in form_data.getlist("mesh") if isinstance(f, UploadFile) and f.filename]
    files, left = [], MAX_UPLOAD_BYTES
    for f in given[:upload_files.MAX_FILES + 1]:
        data = await f.read(left + 1)
        if len(data) > left:
            what = upload_files.last_part(f.filename or "") if len(given) == 1 else "the files sent"
            raise errors.BadUpload(f"{what} {'is' if len(given) == 1 else 'are'} larger than "
                                   f"{MAX_UPLOAD_BYTES // (1024 * 1024)} MB", status_code=413)
        left -= len(data)
        files.append((f.filename or "", data))
    try:
        return upload_files.collect(files, MAX_UPLOAD_BYTES)
    except upload_files.BadFiles as why:
        raise errors.BadUpload(why.message, status_code=why.status_code) from None


@app.post("/upload", response_class=HTMLResponse)
async def upload(request: Request) -> HTMLResponse:
    form_data = await request.form()
    sent = await read_upload(form_data)
    params = {key: value for key, value in form_data.items() if isinstance(value, str)}
    try:
        form, rows = await run_in_threadpool(rank_upload, sent.mesh, sent.texture, params, sent.notes)
    except psycopg.Error as error:
        raise errors.ServerRefused(sent.name, error) from error
    # The upload in 3D beside its ranking (its view.json is made when the page asks for it).
    view_src = (f"/upload/{viewdata.keep_upload(sent.name, sent.mesh, sent.texture, sent.materials)}/view.json"
                if three_installed() else None)
    return page(request, "ranked.html", query=None, upload_name=sent.name, rows=rows, action=None,
                upload_view=view_src, upload_texture=sent.texture_name, upload_notes=sent.notes, **form)


@app.get("/upload/{key}/view.json")
async def upload_view(key: str) -> Response:
    """The 3D view's data of a recent upload; a reason as {"error": ...} when there is none."""
    try:
        shown = await run_in_threadpool(viewdata.convert_upload, key)
    except viewdata.ViewUnavailable as why:
        return unavailable(why)
    return Response(shown.data, media_type="application/json", headers={"Cache-Control": "max-age=3600"})


@app.get("/upload/{key}/texture")
@app.get("/upload/{key}/texture/{index}")
async def upload_texture(key: str, index: int = 0) -> Response:
    """Image INDEX of the textures an upload's 3D view maps (a GLB's own, an OBJ's sent with
    it); a reason as {"error": ...} when there is none."""
    try:
        shown = await run_in_threadpool(viewdata.convert_upload, key)
    except viewdata.ViewUnavailable as why:
        return unavailable(why)
    return texture_response(shown, "the upload", index)
