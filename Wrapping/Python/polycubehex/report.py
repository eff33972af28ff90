# SPDX-License-Identifier: BSD-3-Clause
"""The quality report as Markdown or as one self-contained HTML page (pure Python, no VTK)::

    from polycubehex.report import write_report
    write_report("report.html", report, model="torus.obj", settings={"hexes": 5000},
                 pictures=[("Hex mesh coloured by scaled Jacobian", "torus_hexes.png")])

`report` is the dict of ``polycubehex.mesh()`` (or the same keys gathered in pvbatch): the
measures of REPORT_FIELDS, "tets" and "seconds" per stage, optionally "warnings". Both formats
take their rows from ``report_rows``, so the two tables cannot disagree.
"""
import datetime
import html
import os
import urllib.parse

# The quality measures of DESIGN.md section 4, in the order the report prints them.
REPORT_FIELDS = ["HexCount", "PaddingHexCount", "ScaledJacobianMin", "ScaledJacobianMean",
                 "InvertedHexCount", "ValidHexMesh", "IrregularBoundaryVertexCount",
                 "DistanceMean", "DistanceHausdorff", "CornerCount", "BettiNumber",
                 "PolycubeResidual", "Guidance", "RoundingInvertedTetCount"]

NOTE = ("Distances in units of 1e-3 of the bounding-box diagonal. ValidHexMesh 0 means some hex"
        " is inverted or degenerate (see the warnings).")


def report_rows(report):
    """The quality table as (measure, text) pairs: tets, REPORT_FIELDS present, seconds."""
    rows = [("tets", "%d" % report["tets"])]
    for name in REPORT_FIELDS:
        if name in report:
            value = report[name]
            text = value if isinstance(value, str) else (
                "%d" % value if float(value).is_integer() else "%.4g" % value)
            rows.append((name, text))
    for stage, value in report["seconds"].items():
        rows.append(("seconds: %s" % stage, "%.2f" % value))
    return rows


def format_report(report):
    """The quality table as Markdown lines (what the command line prints)."""
    return "\n".join(["| measure | value |", "|---|---|"] +
                     ["| %s | %s |" % row for row in report_rows(report)])


def format_markdown(report, model, settings=None, pictures=(), date=None):
    """A whole Markdown report: title, settings, table, note, warnings, pictures."""
    date = date or datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    lines = ["# PolycubeHex report: %s" % os.path.basename(model), "",
             "Input `%s`, %s." % (model, date)]
    if settings:
        lines.append("Settings: %s." % "; ".join("%s: %s" % item for item in settings.items()))
    lines += ["", format_report(report), "", NOTE.replace("ValidHexMesh", "`ValidHexMesh`"), ""]
    for warning in report.get("warnings", []):
        lines.append("- warning: %s" % warning)
    for caption, picture in pictures:
        lines += ["", "## " + caption, "", "![%s](%s)" % (caption, picture)]
    return "\n".join(lines) + "\n"


# Kept inside the page so that report.html is one file (the pictures are beside it).
_STYLE = """
body { font-family: sans-serif; max-width: 1040px; margin: 2em auto; color: #222; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.8em; text-align: left; }
td.value { text-align: right; font-family: monospace; }
tr.invalid td { background: #fdd; }
figure { margin: 2em 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-style: italic; margin-top: 0.3em; }
.warning { color: #a40; }
"""


def format_html(report, model, settings=None, pictures=(), date=None):
    """A whole report as one HTML page; pictures are (caption, relative path) pairs."""
    e = html.escape
    date = date or datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    title = "PolycubeHex report: %s" % os.path.basename(model)
    parts = ["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
             "<title>%s</title>" % e(title), "<style>%s</style>" % _STYLE, "</head>", "<body>",
             "<h1>%s</h1>" % e(title), "<table class=\"settings\">",
             "<tr><th>input</th><td>%s</td></tr>" % e(model),
             "<tr><th>date</th><td>%s</td></tr>" % e(date)]
    for name, value in (settings or {}).items():
        parts.append("<tr><th>%s</th><td>%s</td></tr>" % (e(str(name)), e(str(value))))
    parts += ["</table>", "<h2>Quality</h2>", '<table class="quality">',
              "<tr><th>measure</th><th>value</th></tr>"]
    for name, text in report_rows(report):
        # The one line a reader must not miss: an invalid mesh is highlighted.
        invalid = name == "ValidHexMesh" and text != "1"
        parts.append('<tr%s><td>%s</td><td class="value">%s</td></tr>' % (
            ' class="invalid"' if invalid else "", e(name), e(text)))
    parts += ["</table>", "<p>%s</p>" % e(NOTE)]
    warnings = report.get("warnings", [])
    if warnings:
        parts.append("<ul>%s</ul>" % "".join(
            '<li class="warning">%s</li>' % e(w) for w in warnings))
    if pictures:
        parts.append("<h2>Stages</h2>")
    for caption, picture in pictures:
        # A relative URL: the page keeps working when the folder moves with its pictures.
        src = e(urllib.parse.quote(picture))
        parts += ["<figure>", '<img src="%s" alt="%s">' % (src, e(caption)),
                  "<figcaption>%s</figcaption>" % e(caption), "</figure>"]
    parts += ["</body>", "</html>"]
    return "\n".join(parts) + "\n"


def write_report(path, report, model, settings=None, pictures=(), date=None):
    """Writes HTML when `path` ends in .html or .htm, Markdown otherwise."""
    is_html = os.path.splitext(path)[1].lower() in (".html", ".htm")
    text = (format_html if is_html else format_markdown)(report, model, settings, pictures, date)
    with open(path, "w", encoding="utf-8") as out:
        out.write(text)
    return path
