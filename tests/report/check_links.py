#!/usr/bin/env python3
"""Parses a report page (gallery/index.html) and checks that every file it links to exists:
each <img src>, <a href>, <link href> and <script src>, resolved relative to the page.
In-page anchors (#id) must name an element id. Absolute or network URLs are errors: the
report must work offline from the folder alone.

    python3 tests/report/check_links.py gallery/index.html     exit 0, or 1 listing each bad link
"""
import html.parser
import os
import sys
import urllib.parse


class LinkCollector(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        for name in ("src", "href"):
            if a.get(name) is not None and tag in ("img", "a", "link", "script", "source", "iframe"):
                self.links.append((tag, name, a[name]))


def bad_links(page):
    """A list of 'tag attr=value: why' strings, empty when every link resolves."""
    with open(page, encoding="utf-8") as f:
        collector = LinkCollector()
        collector.feed(f.read())
    base = os.path.dirname(os.path.abspath(page))
    problems = []
    for tag, attr, value in collector.links:
        url = urllib.parse.urlsplit(value)
        where = f"<{tag} {attr}=\"{value}\">"
        if url.scheme or url.netloc or value.startswith("/"):
            problems.append(f"{where}: not a relative link (the report must work offline)")
        elif not url.path:
            if url.fragment not in collector.ids:
                problems.append(f"{where}: no element has id \"{url.fragment}\"")
        elif not os.path.isfile(os.path.join(base, urllib.parse.unquote(url.path))):
            problems.append(f"{where}: {os.path.join(base, url.path)} does not exist")
    return problems, len(collector.links)


def main(argv):
    if len(argv) != 2:
        print("usage: check_links.py PAGE.html", file=sys.stderr)
        return 2
    problems, count = bad_links(argv[1])
    for p in problems:
        print(f"{argv[1]}: error: {p}")
    if problems:
        return 1
    print(f"{argv[1]}: all {count} links resolve")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
