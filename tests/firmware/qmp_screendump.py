#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""QMP client for the firmware test (Python standard library only).

qmp_screendump.py SOCKET LOG DUMP TIMEOUT PID [SERIAL_SOCKET]

Connects to QEMU's QMP socket, waits until the firmware writes "frame done"
to LOG (its semihosting output), takes a screendump into DUMP (an absolute
path: QEMU resolves it, not us), then releases the firmware so that it exits
with its own status, and waits for QEMU to close the connection.  Release:
the "up" key (QMP send-key; the lm3s6965evb's gamepad), or with
SERIAL_SOCKET (QEMU's -serial unix:SERIAL_SOCKET,server=on,wait=off) one
byte sent to the board's UART0 (the lm3s811evb has no keys in QEMU).  If QEMU
does not go away it is told to quit and the client fails.  Every wait is
bounded by TIMEOUT seconds, and a QEMU (PID) that exits early ends the
wait at once.  Exit status 0 on success.
"""
import json
import os
import socket
import sys
import time


def fail(msg):
    sys.stderr.write("qmp: %s\n" % msg)
    sys.exit(1)


class Qmp:
    def __init__(self, path, deadline):
        self.deadline = deadline
        while True:
            try:
                self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                self.sock.connect(path)
                break
            except OSError:
                self.sock.close()
                if time.monotonic() > deadline:
                    fail("no QMP socket at %s" % path)
                time.sleep(0.05)
        self.buf = b""
        greeting = self.read()
        if "QMP" not in greeting:
            fail("unexpected greeting %r" % greeting)

    def read(self):
        """One JSON message (QMP sends one per line)."""
        while b"\n" not in self.buf:
            left = self.deadline - time.monotonic()
            if left <= 0:
                fail("timed out waiting for QEMU")
            self.sock.settimeout(left)
            try:
                chunk = self.sock.recv(65536)
            except socket.timeout:
                fail("timed out waiting for QEMU")
            except ConnectionResetError:
                # QEMU exiting with our bytes unread resets rather than closes
                raise EOFError
            if not chunk:
                raise EOFError
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return json.loads(line.decode())

    def command(self, name, arguments=None):
        msg = {"execute": name}
        if arguments is not None:
            msg["arguments"] = arguments
        self.sock.sendall(json.dumps(msg).encode() + b"\n")
        while True:  # skip asynchronous events
            reply = self.read()
            if "return" in reply:
                return reply["return"]
            if "error" in reply:
                fail("%s: %s" % (name, reply["error"].get("desc", reply)))


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass
    # a zombie child of our parent still answers kill(0): look at its state
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return True


def wait_for_text(path, text, deadline, pid):
    while time.monotonic() < deadline:
        if not alive(pid):
            break
        try:
            with open(path, "r", errors="replace") as f:
                content = f.read()
            if text in content:
                return
            if "stipple: " in content and ("fault" in content or ": error" in content):
                break
        except OSError:
            pass
        time.sleep(0.05)
    fail("the firmware did not report '%s' (see %s)" % (text, path))


def send_serial_byte(path, deadline):
    """One byte to the guest's UART through QEMU's serial socket."""
    while True:
        s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            s.connect(path)
            s.settimeout(max(deadline - time.monotonic(), 0.1))
            s.sendall(b"\n")
            # keep the connection until QEMU exits: a byte still in the
            # socket when it is closed may never reach the UART
            return s
        except OSError:
            s.close()
            if time.monotonic() > deadline:
                fail("no serial socket at %s" % path)
            time.sleep(0.05)


def main():
    if len(sys.argv) not in (6, 7):
        fail("usage: qmp_screendump.py SOCKET LOG DUMP TIMEOUT PID [SERIAL_SOCKET]")
    sock_path, log, dump = sys.argv[1], sys.argv[2], sys.argv[3]
    timeout, pid = float(sys.argv[4]), int(sys.argv[5])
    if not os.path.isabs(dump):
        fail("the screendump path must be absolute")
    deadline = time.monotonic() + timeout
    qmp = Qmp(sock_path, deadline)
    qmp.command("qmp_capabilities")
    wait_for_text(log, "frame done", deadline, pid)
    qmp.command("screendump", {"filename": dump})
    serial = None
    if len(sys.argv) == 7:
        serial = send_serial_byte(sys.argv[6], deadline)
    else:
        qmp.command("send-key", {"keys": [{"type": "qcode", "data": "up"}]})
    try:
        while True:
            qmp.read()  # events until QEMU closes the socket on exit
    except EOFError:
        if serial is not None:
            serial.close()
        return 0
    except SystemExit:
        try:
            qmp.deadline = time.monotonic() + 5
            qmp.command("quit")
        except (SystemExit, EOFError, OSError):
            pass
        fail("the firmware did not exit after the key press")


if __name__ == "__main__":
    sys.exit(main())
