#!/usr/bin/env python3
"""A tiny stand-in for a ComfyUI server's HTTP API, for comfyui_test.sh.

    fake_comfyui_server.py PORT_FILE --video FILE [--lifetime S] [--log FILE]

Listens on 127.0.0.1 on an ephemeral port, writes the port number to PORT_FILE once it is
listening, and exits by itself after --lifetime seconds (default 60). Standard library only.

    POST /upload/image   multipart/form-data with a file field "image" -> {"name": ..., ...}
                         (400 when the field is missing or not a PNG)
    POST /prompt         {"prompt": {...}, "client_id": ...} -> {"prompt_id": "...", ...}
    GET  /history/<id>   {} while "running", then {id: {"outputs": ..., "status": ...}}
    GET  /view?filename=&subfolder=&type=   the bytes of --video (404 for another name)

The behaviour is chosen by a node input "mode" in the queued workflow:

    ok          the first history poll is empty, the second lists a "gifs" output
                "svgm_<id>.mp4" (subfolder "sub dir", type "output") served from --video
    webm        the same, but the output is named "svgm_<id>.webm" (served bytes: --video)
    hang        the history stays empty forever
    http500     POST /prompt answers HTTP 500 every time
    bad_output  the history lists outputs with no file in them

With --log, every request is appended to FILE as one JSON line: {"method", "path", "body"}
(the body parsed as JSON for /prompt; for /upload/image {"field", "filename", "size", "png"}).
"""
import argparse
import json
import re
import sys
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

lock = threading.Lock()
prompts = {}  # prompt_id -> {"mode": ..., "polls": n}
counter = [1000]
args = None


def log(entry):
    if args.log:
        with lock, open(args.log, "a") as f:
            f.write(json.dumps(entry) + "\n")


def find_mode(workflow):
    if isinstance(workflow, dict):
        for node in workflow.values():
            if isinstance(node, dict) and isinstance(node.get("inputs"), dict):
                mode = node["inputs"].get("mode")
                if isinstance(mode, str):
                    return mode
    return "ok"


def parse_multipart(content_type, data):
    """Returns {field: (filename, bytes)} of a multipart/form-data body."""
    m = re.search(r'boundary="?([^";]+)"?', content_type or "")
    if not m:
        return {}
    boundary = b"--" + m.group(1).encode()
    fields = {}
    for part in data.split(boundary)[1:]:
        if part.startswith(b"--"):
            break
        head, _, body = part.lstrip(b"\r\n").partition(b"\r\n\r\n")
        body = body[:-2] if body.endswith(b"\r\n") else body
        name = re.search(rb'name="([^"]*)"', head)
        filename = re.search(rb'filename="([^"]*)"', head)
        if name:
            fields[name.group(1).decode()] = (filename.group(1).decode() if filename else None, body)
    return fields


class Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"

    def log_message(self, *a):
        pass

    def reply(self, status, body, content_type="application/json"):
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_POST(self):
        length = int(self.headers.get("Content-Length") or 0)
        data = self.rfile.read(length)
        if self.path == "/upload/image":
            fields = parse_multipart(self.headers.get("Content-Type"), data)
            image = fields.get("image")
            entry = {"field": "image" if image else None, "filename": image[0] if image else None,
                     "size": len(image[1]) if image else 0,
                     "png": bool(image) and image[1].startswith(b"\x89PNG\r\n\x1a\n")}
            log({"method": "POST", "path": self.path, "body": entry})
            if not entry["png"]:
                return self.reply(400, {"error": "no PNG in field image"})
            return self.reply(200, {"name": "svgm_upload.png", "subfolder": "", "type": "input"})
        if self.path == "/prompt":
            try:
                body = json.loads(data)
            except ValueError:
                body = None
            log({"method": "POST", "path": self.path, "body": body})
            if not isinstance(body, dict) or not isinstance(body.get("prompt"), dict):
                return self.reply(400, {"error": {"message": "no prompt"}})
            mode = find_mode(body["prompt"])
            if mode == "http500":
                return self.reply(500, {"error": "simulated failure"})
            with lock:
                counter[0] += 1
                pid = str(counter[0])
                prompts[pid] = {"mode": mode, "polls": 0}
            return self.reply(200, {"prompt_id": pid, "number": 0, "node_errors": {}})
        self.reply(404, {"error": "not found"})

    def do_GET(self):
        url = urllib.parse.urlsplit(self.path)
        log({"method": "GET", "path": self.path, "body": None})
        if url.path.startswith("/history/"):
            pid = urllib.parse.unquote(url.path[len("/history/"):])
            with lock:
                p = prompts.get(pid)
                if p:
                    p["polls"] += 1
            if not p or p["mode"] == "hang" or p["polls"] < 2:
                return self.reply(200, {})
            status = {"status_str": "success", "completed": True, "messages": []}
            if p["mode"] == "bad_output":
                return self.reply(200, {pid: {"outputs": {"9": {"text": ["no video"]}}, "status": status}})
            ext = "webm" if p["mode"] == "webm" else "mp4"
            out = {"filename": "svgm_%s.%s" % (pid, ext), "subfolder": "sub dir", "type": "output"}
            return self.reply(200, {pid: {"outputs": {"3": {"text": ["x"]}, "9": {"gifs": [out]}},
                                          "status": status}})
        if url.path == "/view":
            q = urllib.parse.parse_qs(url.query)
            name = q.get("filename", [""])[0]
            if not re.fullmatch(r"svgm_\d+\.(mp4|webm)", name) or q.get("subfolder") != ["sub dir"] \
                    or q.get("type") != ["output"]:
                return self.reply(404, {"error": "no such file"})
            with open(args.video, "rb") as f:
                return self.reply(200, f.read(), "video/mp4")
        self.reply(404, {"error": "not found"})


def main():
    global args
    ap = argparse.ArgumentParser()
    ap.add_argument("port_file")
    ap.add_argument("--video", required=True)
    ap.add_argument("--lifetime", type=float, default=60)
    ap.add_argument("--log")
    args = ap.parse_args()
    server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    server.daemon_threads = True
    with open(args.port_file + ".tmp", "w") as f:
        f.write(str(server.server_address[1]))
    import os
    os.replace(args.port_file + ".tmp", args.port_file)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    time.sleep(args.lifetime)
    server.shutdown()
    sys.exit(0)


if __name__ == "__main__":
    main()
