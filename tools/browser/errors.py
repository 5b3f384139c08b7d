"""How the browser answers what goes wrong: a page with the reason (the server's message and SQLSTATE), never a traceback."""

from __future__ import annotations

import logging
from typing import Optional

import psycopg
from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse
from fastapi.templating import Jinja2Templates
from starlette.exceptions import HTTPException

log = logging.getLogger("arg.browser")


class PageError(Exception):
    """An error shown to the reader as a page: a title, a message, maybe a SQLSTATE."""

    status_code = 500
    title = "Something went wrong"

    def __init__(self, message: str, *, status_code: Optional[int] = None,
                 sqlstate: Optional[str] = None, detail: Optional[str] = None) -> None:
        super().__init__(message)
        self.message = message
        self.sqlstate = sqlstate
        self.detail = detail
        if status_code is not None:
            self.status_code = status_code


class NotFound(PageError):
    status_code = 404
    title = "Not found"


class BadUpload(PageError):
    status_code = 400
    title = "Nothing to search with"


def _status_of(sqlstate: str) -> int:
    # The file's fault: data the server cannot read (class 22) or over one of arg_build's caps
    # (54000). A cancelled or timed-out build (57014) or a server out of memory (53xxx) may work
    # later. Anything else is the browser's or the database's fault.
    if sqlstate.startswith("22"):
        return 422
    if sqlstate.startswith("54"):
        return 413
    if sqlstate == "57014" or sqlstate.startswith("53"):
        return 503
    return 500


class ServerRefused(PageError):
    """The database refused an uploaded mesh: its message and SQLSTATE, as the server said them."""

    title = "The server could not search with this file"

    def __init__(self, filename: str, error: psycopg.Error) -> None:
        state = error.sqlstate or ""
        message = error.diag.message_primary or str(error).strip() or type(error).__name__
        detail = error.diag.message_detail or error.diag.message_hint
        super().__init__(f"{filename}: {message}", status_code=_status_of(state),
                         sqlstate=state or None, detail=detail)


def install(app: FastAPI, templates: Jinja2Templates) -> None:
    """Registers the handlers that turn exceptions into error pages."""

    def error_page(request: Request, status: int, title: str, message: str,
                   sqlstate: Optional[str] = None, detail: Optional[str] = None) -> HTMLResponse:
        return templates.TemplateResponse(
            "error.html", {"request": request, "title": title, "message": message,
                           "sqlstate": sqlstate, "detail": detail, "status": status},
            status_code=status)

    @app.exception_handler(PageError)
    async def page_error(request: Request, error: PageError) -> HTMLResponse:
        return error_page(request, error.status_code, error.title, error.message, error.sqlstate,
                          error.detail)

    @app.exception_handler(RequestValidationError)
    async def bad_request(request: Request, error: RequestValidationError) -> HTMLResponse:
        where = "; ".join(f"{'.'.join(map(str, e['loc']))}: {e['msg']}" for e in error.errors())
        return error_page(request, 400, "Bad request", where)

    @app.exception_handler(HTTPException)
    async def http_error(request: Request, error: HTTPException) -> HTMLResponse:
        return error_page(request, error.status_code, "Not found" if error.status_code == 404
                          else "Bad request", str(error.detail))

    @app.exception_handler(psycopg.Error)
    async def database_error(request: Request, error: psycopg.Error) -> HTMLResponse:
        # Not an upload (those are ServerRefused): the catalogue itself could not be read, say
        # because the cluster is down. The reader gets the server's words, the log the rest.
        log.error("database error on %s: %s", request.url.path, error)
        state = error.sqlstate
        status = 404 if state == "22023" else 503 if isinstance(error, psycopg.OperationalError) else 500
        message = error.diag.message_primary or str(error).strip() or type(error).__name__
        return error_page(request, status, "The catalogue could not answer", message, state)

    @app.exception_handler(Exception)
    async def internal_error(request: Request, error: Exception) -> HTMLResponse:
        log.exception("internal error on %s", request.url.path)
        return error_page(request, 500, "Internal error",
                          f"{type(error).__name__}: the browser's log has the details")

