"""A link and resource checker for a static HTML site, driven through a real browser: Debian's
Chromium, headless, by WebDriver (chromium-driver, python3-selenium).

check_site(root) serves the folder `root` on a free port of 127.0.0.1 (http.server), loads every
*.html page under it in Chromium and reports, page by page:

* every error the browser's console shows: a stylesheet, script, image or font that fails to load
  ("Failed to load resource: ... 404"), a script error;
* every <img> that did not render (not complete, or naturalWidth 0);
* every internal <a href> and <link href> (same host: next/previous page, index, search,
  stylesheets) whose target does not answer HTTP 200, or whose #fragment
  names no element of the target page (id, or name of an <a>);
* a page without a title.

Links to other hosts are counted, not followed (the machines have no network). The result is a
Report; report.problems is empty for a clean site.
"""
import contextlib
import sys
import functools
import http.server
import threading
import urllib.error
import urllib.parse
import urllib.request
from dataclasses import dataclass, field
from pathlib import Path

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"

# Run in the page after it loaded: what the checks need, in one round trip.
PAGE_SCRIPT = """
const ids = Array.from(document.querySelectorAll('[id]'), e => e.id)
  .concat(Array.from(document.querySelectorAll('a[name]'), e => e.getAttribute('name')));
const links = Array.from(document.querySelectorAll('a[href], link[href]'), a => a.href);
const images = Array.from(document.images, i => ({src: i.currentSrc || i.src, complete: i.complete,
                                                  width: i.naturalWidth}));
return {title: document.title, ids: ids, links: links, images: images};
"""


@dataclass
class Report:
    pages: list = field(default_factory=list)           # the pages loaded (paths relative to root)
    images: dict = field(default_factory=dict)           # page -> its <img> sources (rendered unless a problem says not)
    ids: dict = field(default_factory=dict)              # page -> the ids of its elements
    internal_links: int = 0                              # internal <a href> checked
    external_links: int = 0                              # links to other hosts, not followed
    problems: list = field(default_factory=list)         # one line each


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):
        pass


class _QuietServer(http.server.ThreadingHTTPServer):
    daemon_threads = True

    def handle_error(self, request, client_address):
        # The browser drops connections it no longer needs (a navigation cancels pending loads).
        if not isinstance(sys.exc_info()[1], ConnectionError):
            super().handle_error(request, client_address)


@contextlib.contextmanager
def serve(root):
    """Serves `root` on 127.0.0.1 at a free port; yields the base URL (ending in /)."""
    handler = functools.partial(_QuietHandler, directory=str(root))
    server = _QuietServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


@contextlib.contextmanager
def chromium():
    """Headless Chromium under WebDriver, with the browser console's log kept."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    # As root in a container Chromium needs --no-sandbox; no GPU here; /dev/shm may be small.
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--window-size=1280,900", "--no-first-run", "--disable-extensions"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    driver.set_page_load_timeout(60)
    try:
        yield driver
    finally:
        driver.quit()


def _status(url):
    try:
        with urllib.request.urlopen(url, timeout=10) as response:
            return response.status
    except urllib.error.HTTPError as error:
        return error.code
    except OSError as error:
        return f"unreachable ({error})"


def check_site(root, driver=None):
    """Loads every page of the site in `root` (a folder) and returns a Report."""
    root = Path(root)
    report = Report()
    with contextlib.ExitStack() as stack:
        base = stack.enter_context(serve(root))
        if driver is None:
            driver = stack.enter_context(chromium())
        host = urllib.parse.urlsplit(base).netloc
        ids = {}        # page URL (no fragment) -> ids on the page
        links = []      # (page, link URL)

        def visit(path, url):
            driver.get_log("browser")  # drop what an earlier page left
            driver.get(url)
            info = driver.execute_script(PAGE_SCRIPT)
            for entry in driver.get_log("browser"):
                # The browser asks for /favicon.ico by itself when a page names no icon: not a link.
                if entry.get("level") == "SEVERE" and not entry.get("message", "").startswith(base + "favicon.ico "):
                    report.problems.append(f"{path}: browser console: {entry.get('message')}")
            ids[url] = set(info["ids"])
            return info

        for page in sorted(root.rglob("*.html")):
            path = page.relative_to(root).as_posix()
            report.pages.append(path)
            info = visit(path, urllib.parse.urljoin(base, urllib.parse.quote(path)))
            report.ids[path] = set(info["ids"])
            report.images[path] = [image["src"] for image in info["images"]]
            if not info["title"].strip():
                report.problems.append(f"{path}: no <title>")
            for image in info["images"]:
                if not image["complete"] or image["width"] == 0:
                    report.problems.append(f"{path}: image not rendered: {image['src']}")
            for link in info["links"]:
                parts = urllib.parse.urlsplit(link)
                if parts.scheme in ("http", "https") and parts.netloc == host:
                    links.append((path, link))
                elif parts.scheme in ("http", "https"):
                    report.external_links += 1

        statuses = {}
        for path, link in links:
            report.internal_links += 1
            target, fragment = urllib.parse.urldefrag(link)
            if target not in statuses:
                statuses[target] = _status(target)
            if statuses[target] != 200:
                report.problems.append(f"{path}: broken link {link}: HTTP {statuses[target]}")
                continue
            if not fragment:
                continue
            if target not in ids:  # a page outside the *.html files (e.g. a folder's index)
                visit(urllib.parse.urlsplit(target).path, target)
            if urllib.parse.unquote(fragment) not in ids[target]:
                report.problems.append(f"{path}: broken anchor {link}: no element with id "
                                       f"'{urllib.parse.unquote(fragment)}' on the target page")
    return report
