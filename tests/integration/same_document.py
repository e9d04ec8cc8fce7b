#!/usr/bin/env python3
"""Checks that an animated SVG is the user's document with only `d` animated.

usage: same_document.py ORIGINAL.svg ANIMATED.svg

Passes (exit 0, prints "same document, N paths animated, M elements moved") when ANIMATED is
ORIGINAL plus <animate attributeName="d"> children of <path> elements: the bytes before and
after the root element are identical, and the element trees (tags, attributes, text,
comments) are equal once those <animate> elements are removed, except that a basic shape may
have become a <path> with the same id and attributes, its geometry attributes replaced by `d`,
and the root may carry the animation's frame rate as `data-svgmotion-fps` (inert: what
`svgmotion render` makes its clips at). Otherwise prints the first difference and exits 1. Standard library only.
"""
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
SHAPES = {"rect", "circle", "ellipse", "line", "polyline", "polygon"}
GEOMETRY = {"x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "x1", "y1", "x2", "y2", "points"}


def parse(path):
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True, insert_pis=True))
    with open(path, "rb") as f:
        data = f.read()
    return data, ET.fromstring(data, parser=parser)


def outside_root(data):
    text = data.decode("utf-8")
    start = re.search(r"<svg[\s>]", text).start()
    end = text.rindex("</svg>") + len("</svg>")
    return text[:start], text[end:]


def local(tag):
    return tag.split("}")[-1] if isinstance(tag, str) else tag


def fail(msg):
    print("different: " + msg)
    sys.exit(1)


animated = 0
ROOT = "/svg"


def compare(o, a, where):
    global animated
    if o.tag != a.tag:
        if local(o.tag) in SHAPES and local(a.tag) == "path":
            oa = {k: v for k, v in o.attrib.items() if k not in GEOMETRY}
            aa = {k: v for k, v in a.attrib.items() if k != "d"}
            if oa != aa or "d" not in a.attrib:
                fail(f"{where}: <{local(o.tag)}> became a path with other attributes: {o.attrib} -> {a.attrib}")
        else:
            fail(f"{where}: <{local(o.tag)}> became <{local(a.tag)}>")
    elif o.attrib != {k: v for k, v in a.attrib.items() if not (where == ROOT and k == "data-svgmotion-fps")}:
        fail(f"{where}: attributes {o.attrib} -> {a.attrib}")
    if (o.text or "") != (a.text or ""):
        fail(f"{where}: text {o.text!r} -> {a.text!r}")
    if (o.tail or "") != (a.tail or ""):
        fail(f"{where}: text after it {o.tail!r} -> {a.tail!r}")
    kids = []
    for c in list(a):
        if local(c.tag) == "animate":
            if local(a.tag) != "path" or c.get("attributeName") != "d":
                fail(f"{where}: an <animate> of {c.get('attributeName')!r} on <{local(a.tag)}>")
            animated += 1
            continue
        kids.append(c)
    ok = list(o)
    if len(ok) != len(kids):
        fail(f"{where}: {len(ok)} children -> {len(kids)}")
    for i, (x, y) in enumerate(zip(ok, kids)):
        compare(x, y, f"{where}/{local(x.tag) if isinstance(x.tag, str) else 'comment'}[{i}]")


def main():
    args = sys.argv[1:]
    odata, oroot = parse(args[0])
    adata, aroot = parse(args[1])
    if outside_root(odata) != outside_root(adata):
        fail("the bytes before or after the root element changed")
    compare(oroot, aroot, "/svg")
    print(f"same document, {animated} paths animated")


main()
