"""See a mesh: the page of ``hmira view`` inline in Jupyter, in an HTML file, or as a PNG.

:func:`view` and ``Mesh._repr_html_`` make the same self-contained page as the CLI (three.js
and the mesh inlined, nothing fetched when it opens); :func:`render` screenshots that page in
headless Chromium. The page's script is compiled into the extension when ``viewer/build.sh``
ran before ``pip install .``; without it these functions raise and say so.
"""
from __future__ import annotations

import html
import json
import os
import shutil
import subprocess
import tempfile
from typing import Any, Optional, Tuple

import numpy as np

from . import _core

__all__ = ["View", "render", "view"]

VIEWS = ("iso", "front", "back", "left", "right", "top", "bottom")
# Names people reach for that the page calls otherwise.
_VIEW_ALIASES = {"side": "right", "isometric": "iso"}

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run"]

_NO_CHROMIUM = ("hmira.render needs Chromium for its headless screenshot, and none was found "
                "(looked at $HMIRA_CHROMIUM, chromium, chromium-browser, google-chrome on PATH): install it with "
                "`apt install chromium` (Debian/Ubuntu) or set HMIRA_CHROMIUM to a Chromium or Chrome binary")


def _require_bundle() -> None:
    if not _core._viewer_bundle_available():
        raise RuntimeError("hmira: this hmira was built without the viewer bundle: run viewer/build.sh "
                           "(needs node and npm), then reinstall (pip install .)")


def _page_input(mesh: Any, name: str) -> Tuple[str, np.ndarray, np.ndarray, np.ndarray, Tuple[int, int, int, int, bool]]:
    """(name, points, offsets, corners, info) for _core._viewer_page, from anything as_mesh takes."""
    from . import Mesh, as_mesh

    if isinstance(mesh, (tuple, list)) and len(mesh) == 2 and not isinstance(mesh, Mesh):
        mesh = tuple(mesh)
    m = as_mesh(mesh)
    topology = m.topology()
    if m._positions().shape[0] != topology.vertices:  # removed vertices still hold slots: drop them
        m = m.copy()
        m.collect_garbage()
    points = np.ascontiguousarray(m._positions(), dtype=np.float64)
    if topology.faces == 0:
        offsets, corners = np.zeros(1, np.uint32), np.zeros(0, np.uint32)
    else:
        try:
            faces = m.faces  # (F, k) when every face has k corners
            offsets = np.arange(0, faces.size + 1, faces.shape[1], dtype=np.uint32)
            corners = np.ascontiguousarray(faces, dtype=np.uint32).ravel()
        except ValueError:  # mixed polygon sizes
            polygons = m.polygons
            offsets = np.zeros(len(polygons) + 1, np.uint32)
            offsets[1:] = np.cumsum([len(p) for p in polygons])
            corners = np.fromiter((v for p in polygons for v in p), dtype=np.uint32, count=int(offsets[-1]))
    closed = topology.faces > 0 and topology.closed
    info = (topology.vertices, topology.edges, topology.faces, topology.genus, closed)
    return name, points, offsets, corners, info


def page_html(mesh: Any, *, compare: Any = None, name: str = "mesh", compare_name: str = "compare") -> str:
    """The viewer page (a whole HTML document) for `mesh`, or `mesh` and `compare` side by side."""
    _require_bundle()
    meshes = [_page_input(mesh, name)]
    if compare is not None:
        meshes.append(_page_input(compare, compare_name))
    return _core._viewer_page(meshes)


def _write_atomically(path: Any, data: bytes) -> None:
    """Writes `data` to `path` through a temporary file beside it, so a failure leaves any old file intact."""
    path = os.fspath(path)
    folder = os.path.dirname(os.path.abspath(path))
    fd, temporary = tempfile.mkstemp(prefix=".hmira-", suffix=".tmp", dir=folder)
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # mkstemp makes 0600; a written file gets the usual mode
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


class View:
    """A viewer page that Jupyter shows inline (an ``<iframe srcdoc>``, which isolates the page's
    script and styles from the notebook). ``.html`` is the whole page; ``save(path)`` writes it."""

    def __init__(self, page: str, height: int = 480) -> None:
        self.html = page
        self.height = height

    def _repr_html_(self) -> str:
        return iframe(self.html, self.height)

    def save(self, path: Any) -> None:
        _write_atomically(path, self.html.encode("utf-8"))

    def __repr__(self) -> str:
        return f"hmira.viewer.View({len(self.html)} characters of HTML)"


def iframe(page: str, height: int = 480) -> str:
    """`page` in an ``<iframe srcdoc>`` (its own document: nothing leaks into or out of the notebook)."""
    return (f'<iframe srcdoc="{html.escape(page, quote=True)}" style="width:100%;height:{int(height)}px;border:0" '
            'sandbox="allow-scripts" title="hmira view"></iframe>')


def view(mesh: Any, *, compare: Any = None, out: Any = None, height: int = 480) -> View:
    """Show a mesh in the viewer of ``hmira view``: orbit, zoom, pan, shading, edges, boundary
    and non-manifold edges in colour, and V/E/F/genus in a corner.

    Parameters
    ----------
    mesh : hmira.Mesh, (vertices, faces) pair, or any object with .vertices and .faces
        Vertices without faces are shown as points.
    compare : same kinds, keyword-only
        A second mesh shown beside the first under the same camera (before and after an edit).
    out : str or os.PathLike, keyword-only
        Also write the page to this HTML file (atomically), to open in any browser, offline.
    height : int, keyword-only
        Height in pixels of the inline frame in a notebook.

    Returns
    -------
    View
        Displays itself inline in Jupyter; ``.html`` holds the page.

    Raises
    ------
    RuntimeError
        The extension was built without the viewer bundle (run viewer/build.sh, then reinstall).
    ValueError
        A mesh that cannot be read as one (as :class:`hmira.Mesh`), or no vertices.
    """
    page = page_html(mesh, compare=compare, name=_name_of(mesh, "mesh"), compare_name=_name_of(compare, "compare"))
    shown = View(page, height)
    if out is not None:
        shown.save(out)
    return shown


def _name_of(mesh: Any, default: str) -> str:
    name = getattr(mesh, "name", None) if not isinstance(mesh, (tuple, list)) else None
    return name if isinstance(name, str) and name else default


def find_chromium() -> Optional[str]:
    """The Chromium binary render() uses: $HMIRA_CHROMIUM, else the first on PATH, else None."""
    chosen = os.environ.get("HMIRA_CHROMIUM")
    if chosen:
        return chosen if os.access(chosen, os.X_OK) else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return "/usr/bin/chromium" if os.access("/usr/bin/chromium", os.X_OK) else None


def _fragment(view_name: str, up: str) -> str:
    name = _VIEW_ALIASES.get(view_name, view_name)
    if name not in VIEWS:
        raise ValueError(f"render: view must be one of {', '.join(VIEWS + tuple(_VIEW_ALIASES))}, got {view_name!r}")
    if up not in ("y", "z"):
        raise ValueError(f"render: up must be 'y' or 'z', got {up!r}")
    return f"view={name}" + ("&up=z" if up == "z" else "")


def render(mesh: Any, path: Any, *, view: str = "iso", up: str = "y", size: Tuple[int, int] = (800, 600), compare: Any = None,
           info: bool = False, timeout: float = 120.0) -> None:
    """Write a picture of the mesh as the viewer draws it, through headless Chromium.

    Parameters
    ----------
    mesh : as :func:`view`
    path : str or os.PathLike
        The picture to write (atomically: a failure leaves an existing file alone), by
        extension: ``.png``; ``.jpg``/``.jpeg`` and ``.webp`` are converted from Chromium's PNG
        with Pillow (ValueError when Pillow is missing); any other extension is refused.
    view : {"iso", "front", "back", "left", "right", "top", "bottom"}, keyword-only
        Where the camera looks from ("side" is "right").
    up : {"y", "z"}, keyword-only
        The axis drawn upwards ("z" for volumes and terrains).
    size : (width, height), keyword-only
        Pixels, each 16..4096.
    compare : keyword-only
        A second mesh drawn in the right half.
    info : bool, keyword-only
        Keep the info corner and the controls in the picture (default: the mesh alone).
    timeout : float, keyword-only
        Seconds to wait for Chromium.

    Raises
    ------
    ValueError
        An extension other than .png, .jpg, .jpeg or .webp, or a .jpg/.webp without Pillow.
    RuntimeError
        No Chromium (install it with ``apt install chromium``), no viewer bundle, or Chromium
        failed or timed out (the message carries its output).
    """
    encode = _encoder_for(path)
    width, height = (int(x) for x in size)
    if not (16 <= width <= 4096 and 16 <= height <= 4096):
        raise ValueError(f"render: size must be two integers in 16..4096, got {tuple(size)}")
    fragment = _fragment(view, up)
    page = page_html(mesh, compare=compare, name=_name_of(mesh, "mesh"), compare_name=_name_of(compare, "compare"))
    chromium = find_chromium()
    if chromium is None:
        raise RuntimeError(_NO_CHROMIUM)
    if not info:
        page = page.replace("</head>", "<style>.hmira-ui{display:none!important}</style>\n</head>", 1)
    with tempfile.TemporaryDirectory(prefix="hmira-render-") as work:
        page_path = os.path.join(work, "page.html")
        with open(page_path, "w", encoding="utf-8") as f:
            f.write(page)
        url = "file://" + page_path + "#" + fragment
        png = _screenshot(chromium, url, work, width, height, timeout)
    _write_atomically(path, encode(png))


def _encoder_for(path: Any) -> Any:
    """The function turning Chromium's PNG bytes into the bytes `path`'s extension asks for;
    ValueError, before any work, for an extension it cannot honour."""
    ext = os.path.splitext(os.fspath(path))[1].lower()
    if ext == ".png":
        return lambda png: png
    formats = {".jpg": "JPEG", ".jpeg": "JPEG", ".webp": "WEBP"}
    if ext not in formats:
        raise ValueError(f"render: cannot write {ext or 'a file without extension'!r}; use .png, .jpg, .jpeg or .webp")
    try:
        from PIL import Image
    except ImportError:
        raise ValueError(f"render: writing {ext} needs Pillow (pip install pillow); .png needs nothing more") from None

    def convert(png: bytes) -> bytes:
        import io

        out = io.BytesIO()
        image = Image.open(io.BytesIO(png))
        if formats[ext] == "JPEG":
            image = image.convert("RGB")  # JPEG has no alpha
        image.save(out, format=formats[ext])
        return out.getvalue()

    return convert


def _screenshot(chromium: str, url: str, work: str, width: int, height: int, timeout: float) -> bytes:
    """The page's PNG once it has drawn: through Playwright when it is importable (it waits for the
    page's render-done flag and sees script errors), else Chromium's own --screenshot with a
    virtual-time budget (timers and frames run until the page is idle)."""
    profile = os.path.join(work, "profile")  # a fresh profile: no state from, or to, the user's browser
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        sync_playwright = None
    if sync_playwright is not None:
        try:
            return _playwright_screenshot(sync_playwright, chromium, url, profile, width, height, timeout)
        except RuntimeError:
            raise
        except Exception as error:  # Playwright's own errors (launch failed, timeout): one clear line
            first = (str(error).strip().splitlines() or [type(error).__name__])[0]
            raise RuntimeError(f"render: Chromium ({chromium}) failed under Playwright: {first}") from error
    return _cli_screenshot(chromium, url, work, profile, width, height, timeout)


def _playwright_screenshot(sync_playwright: Any, chromium: str, url: str, profile: str, width: int, height: int,
                           timeout: float) -> bytes:
    """The screenshot once the page sets window.hmiraRenderDone (or raises on a script error)."""
    errors = []
    with sync_playwright() as p:
        browser = p.chromium.launch_persistent_context(profile, executable_path=chromium, args=CHROMIUM_FLAGS, headless=True,
                                                       viewport={"width": width, "height": height})
        try:
            page = browser.new_page()
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.goto(url, wait_until="commit", timeout=timeout * 1000)
            page.wait_for_function("window.hmiraRenderDone === true || window.hmiraError !== undefined",
                                   timeout=timeout * 1000, polling=20)
            failure = page.evaluate("window.hmiraError")
            if failure is not None or errors:
                raise RuntimeError(f"render: the viewer page failed in Chromium: {failure or errors[0]}")
            return page.screenshot()
        finally:
            browser.close()


def _cli_screenshot(chromium: str, url: str, work: str, profile: str, width: int, height: int, timeout: float) -> bytes:
    out = os.path.join(work, "shot.png")
    command = [chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--hide-scrollbars", f"--window-size={width},{height}",
               "--virtual-time-budget=30000", "--run-all-compositor-stages-before-draw", f"--screenshot={out}", url]
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"render: Chromium ({chromium}) did not finish within {timeout:g} s") from None
    if done.returncode != 0 or not os.path.isfile(out) or os.path.getsize(out) == 0:
        tail = done.stdout.decode("utf-8", "replace").strip().splitlines()[-5:]
        raise RuntimeError(f"render: Chromium ({chromium}) exited with {done.returncode} without a screenshot: " + " | ".join(tail))
    with open(out, "rb") as f:
        return f.read()


# Notebooks: the viewer script (three.js and the viewer, about 0.6 MB) goes to the notebook page once
# per kernel session, as a global of the page (window.hmiraViewerBundle); each Mesh repr after the
# first carries only its mesh and a loader that runs that script inside its frame. The frame is
# therefore sandboxed with allow-same-origin (it reads its parent's global), unlike view()'s page.
_notebook = {"sent": False}

# Runs the bundle the notebook page holds; waits a little for the defining cell's script (it may
# run after the frame loads), then says what to do when the page has no bundle (a notebook reopened
# with outputs from a kernel that had already sent it: display hmira.viewer.notebook_script()).
_LOADER = ("<script>(function(){var tries=0;function go(){var p=null;try{p=window.parent.hmiraViewerBundle;}"
           "catch(e){}if(p){var s=document.createElement('script');s.text=p;document.body.appendChild(s);return;}"
           "if(++tries<50){setTimeout(go,100);return;}document.body.insertAdjacentHTML('beforeend',"
           "'<p style=\"font:13px sans-serif\">hmira: the viewer script is not in this notebook page: display "
           "hmira.viewer.notebook_script() in a cell, or run the first cell that shows a mesh again.</p>');}go();})();"
           "</script>")


def _split_page(page: str) -> Tuple[str, str, str]:
    """(before, bundle, after): the page around its last, inline viewer script."""
    start = page.rindex("<script>")
    end = page.rindex("</script>")
    return page[:start], page[start + len("<script>"):end], page[end + len("</script>"):]


def notebook_script() -> str:
    """HTML that defines the viewer script in the notebook page (what the first Mesh repr of a
    session carries); display it by hand after reopening a saved notebook."""
    _require_bundle()
    bundle = _split_page(page_html(([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [[0, 1, 2]])))[1]
    return "<script>window.hmiraViewerBundle=" + json.dumps(bundle).replace("</", "<\\/") + ";</script>"


def repr_html(mesh: Any) -> str:
    """Mesh._repr_html_: the viewer inline, the viewer script sent to the notebook once per
    session; without the bundle, the text repr and how to get it."""
    if not _core._viewer_bundle_available():
        return (f"<pre>{html.escape(repr(mesh))}</pre><p><small>(no inline viewer: this hmira was built without the "
                "viewer bundle; run viewer/build.sh, then pip install .)</small></p>")
    if mesh.vertex_count == 0:
        return f"<pre>{html.escape(repr(mesh))}</pre>"
    before, bundle, after = _split_page(view(mesh).html)
    page = before + _LOADER + after
    frame = (f'<iframe srcdoc="{html.escape(page, quote=True)}" style="width:100%;height:480px;border:0" '
             'sandbox="allow-scripts allow-same-origin" title="hmira view"></iframe>')
    if _notebook["sent"]:
        return frame
    _notebook["sent"] = True
    return "<script>window.hmiraViewerBundle=" + json.dumps(bundle).replace("</", "<\\/") + ";</script>" + frame
