#!/usr/bin/env python3
"""A local HTTP server that only records what it is asked for, for report_hostile_test.sh.

    logging_http_server.py PORT_FILE LOG_FILE [--lifetime S]

Listens on 127.0.0.1 on an ephemeral port, writes the port number to PORT_FILE once it is
listening, appends one line "METHOD PATH" to LOG_FILE for every request (flushed at once) and
answers each with an empty 404, so a page that fetches from it learns nothing. Exits by itself
after --lifetime seconds (default 120). Standard library only.
"""
import argparse
import http.server
import threading


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("port_file")
    ap.add_argument("log_file")
    ap.add_argument("--lifetime", type=float, default=120)
    args = ap.parse_args()
    lock = threading.Lock()

    class Handler(http.server.BaseHTTPRequestHandler):
        def handle_one_request(self):
            try:
                self.raw_requestline = self.rfile.readline(65537)
                if not self.raw_requestline or not self.parse_request():
                    return
                with lock, open(args.log_file, "a") as log:
                    log.write(f"{self.command} {self.path}\n")
                self.send_response(404)
                self.send_header("Content-Length", "0")
                self.end_headers()
            except OSError:
                pass

        def log_message(self, *_):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    open(args.log_file, "a").close()
    with open(args.port_file + ".part", "w") as f:
        f.write(str(server.server_address[1]))
    import os
    os.replace(args.port_file + ".part", args.port_file)
    threading.Timer(args.lifetime, server.shutdown).start()
    server.serve_forever()


if __name__ == "__main__":
    main()
