"""The catalogue browser's web pages (FastAPI): the grid, an object, "more like this", search by upload."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Dict, List, Mapping

import psycopg
from fastapi import FastAPI, Request
from fastapi.responses import FileResponse, HTMLResponse, PlainTextResponse, Response
from fastapi.templating import Jinja2Templates
from starlette.concurrency import run_in_threadpool
from starlette.datastructures import UploadFile

import catalogue
import errors
import pgarg

HERE = Path(__file__).resolve().parent
templates = Jinja2Templates(directory=str(HERE / "templates"))

# Rows a ranking shows unless the reader picks another number; "all" is the whole catalogue.
DEFAULT_K = 20
K_CHOICES = ["10", "20", "50", "all"]
# An upload larger than this is refused before it reaches the server (arg_build has caps too).
MAX_UPLOAD_BYTES = 64 * 1024 * 1024

app = FastAPI(title="arg catalogue browser", docs_url=None, redoc_url=None, openapi_url=None)
errors.install(app, templates)


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


@app.get("/", response_class=HTMLResponse)
def grid(request: Request) -> HTMLResponse:
    params = dict(request.query_params)
    with catalogue.connect() as conn:
        filters = catalogue.chosen_filters(params)
        return page(request, "grid.html", models=catalogue.models(conn, filters), filters=filters,
                    choices=catalogue.filter_choices(conn), total=catalogue.count(conn))


@app.get("/thumbnail/{model_id}.png")
def thumbnail(model_id: int) -> Response:
    with catalogue.connect() as conn:
        png = catalogue.thumbnail(conn, model_id)
    if png is None:
        raise errors.NotFound(f"model {model_id} has no thumbnail")
    return Response(png, media_type="image/png", headers={"Cache-Control": "max-age=3600"})


@app.get("/object/{model_id}", response_class=HTMLResponse)
def object_page(request: Request, model_id: int, level: int = 2) -> HTMLResponse:
    with catalogue.connect() as conn:
        row = catalogue.model(conn, model_id)
        if row is None:
            raise errors.NotFound(f"there is no model {model_id} in the catalogue")
        level = max(0, min(level, row["levels"] - 1))
        return page(request, "object.html", model=row, level=level, levels=range(row["levels"]),
                    choices=catalogue.filter_choices(conn))


@app.get("/object/{model_id}/graph.svg")
def graph(model_id: int, level: int = 2) -> Response:
    with catalogue.connect() as conn:
        svg = catalogue.graph_svg(conn, model_id, level)
    if svg is None:
        raise errors.NotFound(f"there is no model {model_id} in the catalogue")
    # arg_svg has no scripts or references; the policy says so to the browser as well.
    return Response(svg, media_type="image/svg+xml",
                    headers={"Content-Security-Policy": "default-src 'none'; style-src 'unsafe-inline'"})


@app.get("/object/{model_id}/similar", response_class=HTMLResponse)
def similar(request: Request, model_id: int) -> HTMLResponse:
    with catalogue.connect() as conn:
        query = catalogue.model(conn, model_id)
        if query is None:
            raise errors.NotFound(f"there is no model {model_id} in the catalogue")
        form = ranking_form(conn, dict(request.query_params))
        rows = catalogue.ranked(conn, query["descr"], form["k"], form["filters"])
        return page(request, "ranked.html", query=query, rows=rows, action=f"/object/{model_id}/similar",
                    **form)


@app.get("/upload", response_class=HTMLResponse)
def upload_form(request: Request) -> HTMLResponse:
    with catalogue.connect() as conn:
        return page(request, "upload.html", **ranking_form(conn, {}))


def rank_upload(data: bytes, params: Dict[str, str]) -> "tuple[Dict[str, Any], List[Dict[str, Any]]]":
    """The upload's ARG built by the server (the bytes as a bind parameter), then the ranking."""
    with catalogue.connect() as conn:
        form = ranking_form(conn, params)
        query = pgarg.build(conn, data)
        return form, catalogue.ranked(conn, query, form["k"], form["filters"])


@app.post("/upload", response_class=HTMLResponse)
async def upload(request: Request) -> HTMLResponse:
    form_data = await request.form()
    mesh = form_data.get("mesh")
    if not isinstance(mesh, UploadFile) or not mesh.filename:
        raise errors.BadUpload("choose a mesh file (OFF, OBJ, PLY, STL or GLB) to search with")
    data = await mesh.read(MAX_UPLOAD_BYTES + 1)
    if len(data) > MAX_UPLOAD_BYTES:
        raise errors.BadUpload(f"{mesh.filename} is larger than {MAX_UPLOAD_BYTES // (1024 * 1024)} MB",
                               status_code=413)
    params = {key: value for key, value in form_data.items() if isinstance(value, str)}
    try:
        form, rows = await run_in_threadpool(rank_upload, data, params)
    except psycopg.Error as error:
        raise errors.ServerRefused(mesh.filename, error) from error
    return page(request, "ranked.html", query=None, upload_name=mesh.filename, rows=rows,
                action=None, **form)
