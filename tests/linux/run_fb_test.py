#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""stipple_linuxfb against a real kernel.

Boots Debian's own kernel (linux-image-6.1.*-amd64 of Debian 12, fetched with
`apt-get download`, unpacked with dpkg-deb, never installed) under
`qemu-system-x86_64 -accel tcg` with a busybox initramfs that holds fbtest
(statically linked), then checks what the port drew:

  * -vga std:    bochs DRM -> /dev/fb0, 32 bpp XRGB8888: QMP screendump,
                 polled until it matches (DRM shows writes late), compared
                 pixel for pixel with the host's render of the same scene.
  * -vga cirrus: cirrus DRM -> /dev/fb0, 16 bpp RGB565: the same.
  * vfb (vfb.ko from the same package, vfb_enable=1) in the std guest,
    switched with FBIOPUT_VSCREENINFO to 1 bpp (MONO01, panned to an odd
    x offset), 8 bpp (pseudocolour, panned), 16 bpp RGB565 and ARGB1555,
    24 and 32 bpp: the memory is read back through read(2) on /dev/fb1,
    printed base64 on the serial console and compared byte for byte with
    what the fbdev rules (stp_linuxfb.h) say those pixels must be.
  * -vga std with vga=0x318: vesafb (built in), 24 bpp: screendump again.
  * the VT: KD_GRAPHICS while the port is open, KD_TEXT again after close,
    exit() and SIGTERM/SIGINT; open errors are clear messages.
  * with --gpiotest: the panel control lines (stipple_gpio, libgpiod v2)
    against gpio-sim in the std guest; gpio-sim.ko is built out of tree from
    Debian's linux-source/linux-headers of the same version (cached).

The expected bytes are computed here from the reference picture and the
mode the kernel reports, not by the port's own conversion code.

Exit status: 0 pass, 1 fail, 77 skip (no qemu/busybox/kernel package;
set STP_LINUX_TEST_REQUIRED=1 to make that a failure instead).
"""
import argparse
import base64
import concurrent.futures
import json
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
import threading
import time

T0 = time.monotonic()
LOG_LOCK = threading.Lock()


def log(msg):
    with LOG_LOCK:
        print("[%6.2fs] %s" % (time.monotonic() - T0, msg), flush=True)


def skip(msg):
    if os.environ.get("STP_LINUX_TEST_REQUIRED") == "1":
        log("FAIL (required): " + msg)
        sys.exit(1)
    log("SKIP: " + msg)
    sys.exit(77)


def run(cmd, timeout, **kw):
    return subprocess.run(cmd, timeout=timeout, check=True, **kw)


# ------------------------------------------------------------------ kernel

MODULE_DIRS = ["kernel/drivers/gpu/drm", "kernel/drivers/video", "kernel/fs/configfs"]
CACHE_LAYOUT = 2


def fetch_kernel(cache):
    """Returns (vmlinuz path, modules root).  Cached under `cache`."""
    stamp = os.path.join(cache, "kernel.json")
    if os.path.exists(stamp):
        with open(stamp) as f:
            info = json.load(f)
        if info.get("layout") == CACHE_LAYOUT and os.path.exists(info["vmlinuz"]):
            return info
    if not shutil.which("apt-cache") or not shutil.which("dpkg-deb"):
        skip("apt-cache/dpkg-deb not found: cannot fetch Debian's kernel")
    out = subprocess.run(["apt-cache", "search", "--names-only", r"^linux-image-6\.1\.0-[0-9]+-amd64$"],
                         capture_output=True, text=True, timeout=60).stdout
    names = sorted({l.split()[0] for l in out.splitlines() if l.strip()},
                   key=lambda n: int(re.match(r"linux-image-6\.1\.0-(\d+)-amd64", n).group(1)))
    if not names:
        skip("no linux-image-6.1.0-*-amd64 package known to apt (run apt-get update)")
    pkg = names[-1]
    os.makedirs(cache, exist_ok=True)
    for old in os.listdir(cache):
        if old.endswith(".deb"):
            os.unlink(os.path.join(cache, old))
    log("downloading %s" % pkg)
    r = subprocess.run(["apt-get", "download", "-q", pkg], cwd=cache, capture_output=True,
                       text=True, timeout=600)
    debs = [f for f in os.listdir(cache) if f.startswith(pkg) and f.endswith(".deb")]
    if r.returncode != 0 or not debs:
        skip("apt-get download %s failed: %s" % (pkg, r.stderr.strip()[-300:]))
    deb = os.path.join(cache, debs[0])
    root = os.path.join(cache, "root")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    log("unpacking vmlinuz and the display modules")
    tar = subprocess.Popen(["dpkg-deb", "--fsys-tarfile", deb], stdout=subprocess.PIPE)
    subprocess.run(["tar", "-x", "-C", root, "--wildcards", "./boot/vmlinuz-*"]
                   + ["./lib/modules/*/%s/*" % d for d in MODULE_DIRS],
                   stdin=tar.stdout, check=True, timeout=300)
    tar.stdout.close()
    if tar.wait(timeout=60) != 0:
        sys.exit("dpkg-deb failed on %s" % deb)
    version = subprocess.run(["dpkg-deb", "-f", deb, "Version"], capture_output=True, text=True,
                             timeout=60, check=True).stdout.strip()
    os.unlink(deb)
    vmlinuz = [f for f in os.listdir(os.path.join(root, "boot")) if f.startswith("vmlinuz-")][0]
    kver = vmlinuz[len("vmlinuz-"):]
    info = {"package": pkg, "version": version, "layout": CACHE_LAYOUT,
            "vmlinuz": os.path.join(root, "boot", vmlinuz),
            "modroot": os.path.join(root, "lib", "modules", kver)}
    with open(stamp, "w") as f:
        json.dump(info, f)
    return info


def build_gpio_sim(cache, info):
    """gpio-sim.ko for this kernel, built out of tree (Debian does not enable
    CONFIG_GPIO_SIM nor CONFIG_IRQ_SIM): drivers/gpio/gpio-sim.c with
    kernel/irq/irq_sim.c linked in, from linux-source-6.1 of the same
    version, against linux-headers and linux-kbuild.  6.1 does not export
    irq_to_desc to modules, so the simulator hands its interrupts over with
    the exported generic_handle_irq_safe instead.  Returns the path, or None
    and a reason."""
    ko = os.path.join(cache, "gpio-sim.ko")
    if os.path.exists(ko):
        return ko, None
    for tool in ("make", "gcc-12", "xz"):
        if not shutil.which(tool):
            return None, "%s not found (needed to build gpio-sim.ko)" % tool
    abi = re.match(r"linux-image-(.*)-amd64$", info["package"]).group(1)
    ver = info["version"]
    series = ".".join(abi.split(".")[:2])
    build = os.path.join(cache, "gpio-sim-build")
    shutil.rmtree(build, ignore_errors=True)
    os.makedirs(build)
    pkgs = ["linux-headers-%s-amd64=%s" % (abi, ver), "linux-headers-%s-common=%s" % (abi, ver),
            "linux-kbuild-%s=%s" % (series, ver), "linux-source-%s=%s" % (series, ver)]
    log("downloading %s" % " ".join(pkgs))
    r = subprocess.run(["apt-get", "download", "-q"] + pkgs, cwd=build, capture_output=True,
                       text=True, timeout=900)
    if r.returncode != 0:
        return None, "apt-get download failed: %s" % r.stderr.strip()[-300:]
    root = os.path.join(build, "root")
    for deb in os.listdir(build):
        if deb.endswith(".deb") and not deb.startswith("linux-source"):
            run(["dpkg-deb", "-x", os.path.join(build, deb), root], 300)
    src_deb = [d for d in os.listdir(build) if d.startswith("linux-source")][0]
    log("unpacking gpio-sim.c, irq_sim.c and gpiolib.h from %s" % src_deb)
    top = "linux-source-%s" % series
    sh = ("dpkg-deb --fsys-tarfile '%s' | tar -xO ./usr/src/%s.tar.xz | xz -dc | "
          "tar -x -C '%s' %s/drivers/gpio/gpio-sim.c %s/drivers/gpio/gpiolib.h "
          "%s/kernel/irq/irq_sim.c") % (os.path.join(build, src_deb), top, build, top, top, top)
    run(["sh", "-c", sh], 600)
    hdr = os.path.join(root, "usr", "src", "linux-headers-%s-amd64" % abi)
    mk = os.path.join(hdr, "Makefile")
    with open(mk) as f:
        text = f.read()
    with open(mk, "w") as f:  # it includes the common tree by absolute path
        f.write(text.replace("include /usr/src/", "include %s/usr/src/" % root))
    mod = os.path.join(build, "mod")
    os.makedirs(mod)
    shutil.copy(os.path.join(build, top, "drivers/gpio/gpio-sim.c"), os.path.join(mod, "gpio-sim-core.c"))
    shutil.copy(os.path.join(build, top, "drivers/gpio/gpiolib.h"), mod)
    with open(os.path.join(build, top, "kernel/irq/irq_sim.c")) as f:
        irq = f.read()
    old = "handle_simple_irq(irq_to_desc(irqnum));"
    if old not in irq:
        return None, "irq_sim.c of %s has no '%s' to replace" % (ver, old)
    with open(os.path.join(mod, "irq_sim.c"), "w") as f:
        f.write(irq.replace(old, "generic_handle_irq_safe(irqnum);"))
    with open(os.path.join(mod, "Kbuild"), "w") as f:
        f.write("obj-m := gpio-sim.o\ngpio-sim-y := gpio-sim-core.o irq_sim.o\n")
    log("building gpio-sim.ko")
    r = subprocess.run(["make", "-C", hdr, "M=" + mod, "modules"], capture_output=True,
                       text=True, timeout=600)
    if r.returncode != 0:
        return None, "building gpio-sim.ko failed: %s" % (r.stdout + r.stderr)[-800:]
    shutil.copy(os.path.join(mod, "gpio-sim.ko"), ko)
    shutil.rmtree(build, ignore_errors=True)
    return ko, None


def module_index(modroot):
    index = {}
    for d, _, files in os.walk(modroot):
        for f in files:
            if f.endswith(".ko"):
                index[f[:-3].replace("-", "_")] = os.path.join(d, f)
    return index


def module_order(index, wanted):
    """Modules in load order (dependencies first), from .modinfo depends=."""
    order, seen = [], set()

    def deps(name):
        with open(index[name], "rb") as f:
            data = f.read()
        m = re.search(rb"\x00depends=([^\x00]*)\x00", data)
        return [d.decode().replace("-", "_") for d in m.group(1).split(b",") if d] if m else []

    def visit(name):
        if name in seen:
            return
        seen.add(name)
        if name not in index:
            sys.exit("module %s not in the kernel package's display modules" % name)
        for d in deps(name):
            visit(d)
        order.append(name)

    for w in wanted:
        visit(w)
    return order


# ------------------------------------------------------------------ initramfs

def cpio_newc(entries):
    """entries: (name, mode, data bytes or None, rdev major, minor)."""
    out = bytearray()
    ino = 1
    for name, mode, data, major, minor in entries + [("TRAILER!!!", 0, b"", 0, 0)]:
        data = data or b""
        nb = name.encode() + b"\0"
        hdr = "070701" + "".join("%08X" % v for v in (
            ino, mode, 0, 0, 1, 0, len(data), 0, 0, major, minor, len(nb), 0))
        out += hdr.encode() + nb
        out += b"\0" * ((4 - len(out) % 4) % 4)
        out += data
        out += b"\0" * ((4 - len(out) % 4) % 4)
        ino += 1
    return bytes(out)


def build_initramfs(path, busybox, guest, modules, index, script, gpiotest=None):
    ents = [("dev", stat.S_IFDIR | 0o755, None, 0, 0),
            ("dev/console", stat.S_IFCHR | 0o600, None, 5, 1),
            ("bin", stat.S_IFDIR | 0o755, None, 0, 0),
            ("proc", stat.S_IFDIR | 0o755, None, 0, 0),
            ("sys", stat.S_IFDIR | 0o755, None, 0, 0),
            ("mod", stat.S_IFDIR | 0o755, None, 0, 0)]
    with open(busybox, "rb") as f:
        ents.append(("bin/busybox", stat.S_IFREG | 0o755, f.read(), 0, 0))
    with open(guest, "rb") as f:
        ents.append(("fbtest", stat.S_IFREG | 0o755, f.read(), 0, 0))
    if gpiotest:
        with open(gpiotest, "rb") as f:
            ents.append(("gpiotest", stat.S_IFREG | 0o755, f.read(), 0, 0))
    for m in modules:
        with open(index[m], "rb") as f:
            ents.append(("mod/%s.ko" % m, stat.S_IFREG | 0o644, f.read(), 0, 0))
    ents.append(("init", stat.S_IFREG | 0o755, script.encode(), 0, 0))
    with open(path, "wb") as f:
        f.write(cpio_newc(ents))


INIT_HEAD = """#!/bin/busybox sh
/bin/busybox --install -s /bin
mount -t devtmpfs dev /dev
mount -t proc proc /proc
mount -t sysfs sys /sys
echo 0 > /proc/sys/kernel/printk
echo STP-BOOTED
"""


def wait_dev(dev):
    return ("n=0; while [ ! -e %s ] && [ $n -lt 100 ]; do sleep 0.1; n=$((n+1)); done\n" % dev)


# ------------------------------------------------------------------ QEMU

class Guest:
    def __init__(self, qemu, kernel, initrd, vga, work, name, append=""):
        self.serial = os.path.join(work, name + ".serial")
        # Unix socket paths must stay under 108 bytes: a deep build tree
        # would exceed that, so the socket lives in a short folder
        self.sock_dir = tempfile.mkdtemp(prefix="stpq", dir="/tmp")
        self.qmp_path = os.path.join(self.sock_dir, name + ".qmp")
        for p in (self.serial, self.qmp_path):
            if os.path.exists(p):
                os.unlink(p)
        cmd = [qemu, "-accel", "tcg", "-m", "320", "-smp", "1", "-display", "none",
               "-vga", vga, "-no-reboot", "-no-user-config",
               "-kernel", kernel, "-initrd", initrd,
               "-append", "console=ttyS0 quiet loglevel=0 panic=-1 " + append,
               "-serial", "file:" + self.serial,
               "-qmp", "unix:%s,server=on,wait=off" % self.qmp_path,
               "-monitor", "none", "-net", "none"]
        self.proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.qmp = None
        self.buf = b""

    def connect(self, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if self.proc.poll() is not None:
                raise RuntimeError("qemu exited: %s" % self.proc.stdout.read().decode(errors="replace"))
            try:
                s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
                s.settimeout(10)
                s.connect(self.qmp_path)
                self.qmp = s
                self._reply()  # greeting
                self.command("qmp_capabilities")
                return
            except (FileNotFoundError, ConnectionRefusedError):
                time.sleep(0.05)
        raise RuntimeError("no QMP socket within %ss" % timeout)

    def _reply(self):
        while b"\n" not in self.buf:
            chunk = self.qmp.recv(65536)
            if not chunk:
                raise RuntimeError("QMP closed")
            self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return json.loads(line)

    def command(self, name, **args):
        msg = {"execute": name}
        if args:
            msg["arguments"] = args
        self.qmp.sendall(json.dumps(msg).encode() + b"\n")
        while True:
            r = self._reply()
            if "return" in r:
                return r["return"]
            if "error" in r:
                raise RuntimeError("QMP %s: %s" % (name, r["error"]))

    def output(self):
        try:
            with open(self.serial, "rb") as f:
                return f.read().decode(errors="replace").replace("\r", "")
        except FileNotFoundError:
            return ""

    def wait_for(self, pattern, timeout):
        end = time.monotonic() + timeout
        rx = re.compile(pattern, re.M)
        while time.monotonic() < end:
            out = self.output()
            m = rx.search(out)
            if m:
                return m, out
            if self.proc.poll() is not None:
                break
            time.sleep(0.05)
        raise RuntimeError("guest: no /%s/ within %ss; serial so far:\n%s"
                           % (pattern, timeout, self.output()[-3000:]))

    def stop(self):
        if self.proc.poll() is None:
            try:
                if self.qmp:
                    self.qmp.settimeout(2)
                    self.command("quit")
            except (RuntimeError, OSError, ValueError):
                pass
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=5)
        if self.qmp:
            self.qmp.close()
        self.proc.stdout.close()
        shutil.rmtree(self.sock_dir, ignore_errors=True)


# ------------------------------------------------------------------ pictures

def read_pnm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < (3 if data[:2] == b"P4" else 4):
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            while data[pos:pos + 1] not in (b"\n", b""):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    pos += 1
    magic, w, h = fields[0], int(fields[1]), int(fields[2])
    return magic, w, h, data[pos:]


class Expected:
    """The host's render: level(x, y) in 0..255 (mono: 0 or 255), black
    outside the rendered area."""

    def __init__(self, fbtest, work, w, h, mono):
        path = os.path.join(work, "expect-%dx%d-%s.pnm" % (w, h, "mono" if mono else "grey"))
        run([fbtest, "expect", str(w), str(h), "mono" if mono else "grey", path], 60)
        magic, pw, ph, raster = read_pnm(path)
        assert (pw, ph) == (w, h)
        self.w, self.h, self.mono = w, h, mono
        if mono:
            assert magic == b"P4"
            rb = (w + 7) // 8
            # PBM: bit 1 = black; stipple's ON (light) pixels are written as 0
            self.levels = bytes(0 if raster[y * rb + x // 8] & (0x80 >> (x % 8)) else 255
                                for y in range(h) for x in range(w))
        else:
            assert magic == b"P5"
            self.levels = raster[:w * h]

    def level(self, x, y):
        if x < self.w and y < self.h:
            return self.levels[y * self.w + x]
        return 0


def parse_mode(line):
    m = {}
    for k, v in re.findall(r"(\w+)=(\S+)", line):
        if ":" in v:
            a, b = v.split(":")
            m[k] = (int(a), int(b))
        elif k == "id":
            m[k] = v
        else:
            m[k] = int(v)
    return m


def scale(g, length):
    return (g * ((1 << length) - 1) + 127) // 255


def expected_bytes(mode, exp):
    """What the visible rows of the framebuffer memory must hold, as a dict
    offset -> byte for every byte that holds a visible pixel's bits."""
    bpp, line = mode["bpp"], mode["line"]
    xo, yo = mode["xoff"], mode["yoff"]
    want = {}
    if bpp == 1:
        # x86 is little-endian: the kernel's fbdev code puts pixel x at bit
        # x % 8; MONO01 (visual 0) stores a light pixel as 0.
        assert mode["visual"] in (0, 1), mode
        light_bit = 1 if mode["visual"] == 1 else 0
        for y in range(mode["yres"]):
            for x in range(mode["xres"]):
                px = xo + x
                off = (yo + y) * line + px // 8
                bit = light_bit if exp.level(x, y) >= 128 else 1 - light_bit
                want.setdefault(off, [0, 0])
                want[off][0] |= 1 << (px % 8)        # mask of visible bits
                want[off][1] |= bit << (px % 8)
        return want
    nb = bpp // 8
    for y in range(mode["yres"]):
        for x in range(mode["xres"]):
            g = exp.level(x, y)
            if mode["visual"] == 3 and bpp == 8:      # pseudocolour + grey ramp
                v = g
            else:
                v = 0
                for ch in ("red", "green", "blue"):
                    o, n = mode[ch]
                    v |= scale(g, n) << o
                o, n = mode["transp"]
                v |= ((1 << n) - 1) << o
            off = (yo + y) * line + (xo + x) * nb
            for i in range(nb):
                want[off + i] = [0xFF, (v >> (8 * i)) & 0xFF]
    return want


def compare_dump(name, mode, exp, data):
    bad = []
    for off, (mask, val) in expected_bytes(mode, exp).items():
        if off >= len(data):
            bad.append((off, None, val))
        elif data[off] & mask != val:
            bad.append((off, data[off] & mask, val))
    if bad:
        log("%s: %d bytes differ, first: %s" % (name, len(bad),
            ", ".join("@%d got %s want %#x" % b for b in bad[:6])))
        return False
    log("%s: all %d visible pixels right (line %d, offset %d,%d)"
        % (name, mode["xres"] * mode["yres"], mode["line"], mode["xoff"], mode["yoff"]))
    return True


def compare_screendump(path, mode, exp):
    """Quantise each screendump channel back to the framebuffer's field
    length (exact whatever way QEMU widened it) and compare."""
    magic, w, h, raster = read_pnm(path)
    if magic != b"P6" or (w, h) != (mode["xres"], mode["yres"]):
        return "screendump is %s %dx%d, mode is %dx%d" % (magic, w, h, mode["xres"], mode["yres"])
    lens = [mode[c][1] for c in ("red", "green", "blue")]
    bad, first = 0, None
    for y in range(h):
        row = raster[y * w * 3:(y + 1) * w * 3]
        for x in range(w):
            g = exp.level(x, y)
            for c in range(3):
                if row[3 * x + c] >> (8 - lens[c]) != scale(g, lens[c]):
                    bad += 1
                    if first is None:
                        first = (x, y, tuple(row[3 * x:3 * x + 3]), g)
                    break
    if bad:
        return "%d pixels differ, first at (%d,%d): got %s for level %d" % ((bad,) + first)
    return None


# ------------------------------------------------------------------ tests

VFB_W, VFB_H = 203, 150        # visible size (odd, so lines are padded)
VFB_PORT = (180, 130)          # the port is smaller: the rest must be black
VFB_CASES = [
    # name, setmode args (bpp xres yres [xvirt yvirt xoff yoff [argb]])
    ("vfb-1bpp", [1, VFB_W, VFB_H, 211, 160, 3, 2]),
    ("vfb-8bpp", [8, VFB_W, VFB_H, 211, 160, 5, 4]),
    ("vfb-16bpp-rgb565", [16, VFB_W, VFB_H]),
    ("vfb-16bpp-argb1555", [16, VFB_W, VFB_H, VFB_W, VFB_H, 0, 0, "argb"]),
    ("vfb-24bpp", [24, VFB_W, VFB_H]),
    ("vfb-32bpp", [32, VFB_W, VFB_H]),
]


GPIO_SETUP = """G=/sys/kernel/config/gpio-sim/stp
mount -t configfs none /sys/kernel/config
mkdir $G $G/bank0
echo 8 > $G/bank0/num_lines
echo stp-panel > $G/bank0/label
i=0
for n in RST DC BUSY EN BL VCOM; do
  mkdir $G/bank0/line$i; echo $n > $G/bank0/line$i/name; i=$((i+1))
done
echo 1 > $G/live
C=$(cat $G/bank0/chip_name)
""" + wait_dev("/dev/$C") + """/gpiotest /sys/devices/platform/$(cat $G/dev_name)/$C $C
"""


def guest_script(modules, vfb, fbdev_cases, gpio=False):
    s = INIT_HEAD
    for m in modules:
        s += "insmod /mod/%s.ko%s\n" % (m, " vfb_enable=1" if m == "vfb" else "")
    s += wait_dev("/dev/fb0")
    s += "/fbtest errors\n"
    if vfb:
        s += wait_dev("/dev/fb1")
        for name, args in VFB_CASES:
            s += "echo STP-CASE %s\n" % name
            s += "/fbtest setmode /dev/fb1 %s\n" % " ".join(str(a) for a in args)
            s += "/fbtest draw /dev/fb1 %d %d\n" % VFB_PORT
            s += "/fbtest dump /dev/fb1\n"
        s += "/fbtest console /dev/fb1\n"
    if gpio:
        s += GPIO_SETUP
    s += "/fbtest mode /dev/fb0\n"
    s += "/fbtest draw /dev/fb0 0 0 hold &\n"
    s += "sleep 60\npoweroff -f\n"
    return s


def check_common(out):
    ok = True
    errs = re.findall(r"^STP-OPENERR (\S+) (.*)$", out, re.M)
    want = [("refused", "/dev/null: not a framebuffer"),
            ("refused", "/dev/nonexistent-fb: cannot open: No such file or directory")]
    for (st, msg), (wst, wmsg) in zip(errs, want):
        if st != wst or not msg.startswith(wmsg):
            log("open error: got %s %r, want %s %r" % (st, msg, wst, wmsg))
            ok = False
    if len(errs) != 2:
        log("open errors: %d lines" % len(errs))
        ok = False
    return ok


def check_console(out):
    # KD_TEXT = 0, KD_GRAPHICS = 1
    want = [r"^STP-CONSOLE before=0$",
            r"^STP-CONSOLE close during=1 after=0$",
            r"^STP-CONSOLE exit during=1 after=0 status=exit 0$",
            r"^STP-CONSOLE sigterm during=1 after=0 status=signal 15$",
            r"^STP-CONSOLE sigint during=1 after=0 status=signal 2$"]
    ok = True
    for w in want:
        if not re.search(w, out, re.M):
            log("console: missing /%s/" % w)
            ok = False
    if ok:
        log("console: KD_GRAPHICS while open; KD_TEXT after close, exit(), SIGTERM, SIGINT")
    return ok


GPIO_CHECKS = ["open", "initial", "reset", "dc", "enable-backlight", "busy-idle",
               "busy-release", "busy-timeout", "vcom-toggle", "vcom-20hz", "busy-active-low",
               "missing-line", "bad-offset"]


def check_gpio(out):
    ok = True
    for c in GPIO_CHECKS:
        m = re.search(r"^STP-GPIO %s (ok|FAIL) (.*)$" % re.escape(c), out, re.M)
        if not m:
            log("gpio %s: no result" % c)
            ok = False
        else:
            log("gpio %s: %s %s" % (c, m.group(1), m.group(2)))
            ok &= m.group(1) == "ok"
    if not re.search(r"^STP-GPIO-DONE 0 failures$", out, re.M):
        ok = False
    return ok


def boot(args, name, vga, modules, vfb, kernel, index, work, append="", gpio=False):
    initrd = os.path.join(work, name + ".cpio")
    build_initramfs(initrd, args.busybox, args.guest, modules, index,
                    guest_script(modules, vfb, VFB_CASES if vfb else [], gpio),
                    args.gpiotest if gpio else None)
    log("%s: booting (-vga %s, modules %s)" % (name, vga, " ".join(modules)))
    g = Guest(args.qemu, kernel, initrd, vga, work, name, append)
    ok = True
    try:
        g.connect(10)
        g.wait_for(r"^STP-BOOTED", 60)
        log("%s: booted" % name)
        m, out = g.wait_for(r"^STP-DRAWN /dev/fb0 (\d+) ms", 60)
        log("%s: fb0 drawn in the guest (%s ms render)" % (name, m.group(1)))
        ok &= check_common(out)
        if "STP-ERROR" in out:
            log("%s: guest errors:\n%s" % (name, "\n".join(
                l for l in out.splitlines() if l.startswith("STP-ERROR"))))
            ok = False
        if vfb:
            for cname, _ in VFB_CASES:
                cm = re.search(r"^STP-CASE %s\s*$.*?^(STP-MODE .*?)$.*?^STP-DUMP /dev/fb1 (\d+)\s*$"
                               r"(.*?)^STP-END" % re.escape(cname), out, re.M | re.S)
                if not cm:
                    log("%s: no dump in the serial output" % cname)
                    ok = False
                    continue
                mode = parse_mode(cm.group(1))
                data = base64.b64decode("".join(
                    l.strip() for l in cm.group(3).splitlines()
                    if re.fullmatch(r"[A-Za-z0-9+/=]+", l.strip())))
                if len(data) != int(cm.group(2)):
                    log("%s: dump is %d bytes, announced %s" % (cname, len(data), cm.group(2)))
                    ok = False
                    continue
                exp = Expected(args.fbtest, work, VFB_PORT[0], VFB_PORT[1], mode["bpp"] == 1)
                ok &= compare_dump("%s (%s)" % (cname, " ".join(
                    "%s=%s" % (k, mode[k]) for k in ("bpp", "visual", "line"))), mode, exp, data)
            ok &= check_console(out)
        if gpio:
            ok &= check_gpio(out)
        mm = re.search(r"^(STP-MODE /dev/fb0 .*)$", out, re.M)
        mode = parse_mode(mm.group(1))
        exp = Expected(args.fbtest, work, mode["xres"], mode["yres"], mode["bpp"] == 1)
        dump = os.path.join(work, name + "-screendump.ppm")
        end, why, tries = time.monotonic() + 10, "no screendump", 0
        while time.monotonic() < end:
            g.command("screendump", filename=dump)
            tries += 1
            why = compare_screendump(dump, mode, exp)
            if why is None:
                break
            time.sleep(0.1)
        if why:
            log("%s: screendump: %s" % (name, why))
            ok = False
        else:
            log("%s: screendump %dx%d %d bpp (%s, red %s green %s blue %s) matches pixel for "
                "pixel (try %d)" % (name, mode["xres"], mode["yres"], mode["bpp"], mode["id"],
                                     mode["red"], mode["green"], mode["blue"], tries))
    except (RuntimeError, subprocess.SubprocessError, OSError, KeyError, ValueError) as e:
        log("%s: %s" % (name, e))
        ok = False
    finally:
        g.stop()
    if not ok:
        with open(os.path.join(work, name + ".serial"), "rb") as f:
            tail = f.read()[-2000:].decode(errors="replace")
        log("%s: serial tail:\n%s" % (name, tail))
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--fbtest", required=True)
    ap.add_argument("--guest", required=True)
    ap.add_argument("--gpiotest")
    ap.add_argument("--jobs", type=int, default=0, help="guests at once (default: cores)")
    ap.add_argument("--cache", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--qemu", default=shutil.which("qemu-system-x86_64"))
    ap.add_argument("--busybox", default="/bin/busybox")
    ap.add_argument("--only", choices=["std", "cirrus", "vesa"])
    args = ap.parse_args()
    if not args.qemu:
        skip("qemu-system-x86_64 not found (Debian: qemu-system-x86)")
    if not os.path.exists(args.busybox):
        skip("%s not found (Debian: busybox-static)" % args.busybox)
    with open(args.busybox, "rb") as f:
        if b"/lib64/ld-linux" in f.read(4096):
            skip("%s is dynamically linked (Debian: busybox-static)" % args.busybox)
    os.makedirs(args.work, exist_ok=True)
    info = fetch_kernel(args.cache)
    kernel, index = info["vmlinuz"], module_index(info["modroot"])
    log("kernel %s (%s %s)" % (kernel, info["package"], info["version"]))
    ok = True
    gpio = False
    if args.gpiotest and args.only in (None, "std"):
        ko, why = build_gpio_sim(args.cache, info)
        if ko:
            index["gpio_sim"] = ko
            gpio = True
        elif os.environ.get("STP_LINUX_TEST_REQUIRED") == "1":
            log("FAIL (required): gpio-sim: %s" % why)
            ok = False
        else:
            log("gpio-sim not available, GPIO checks skipped: %s" % why)
    elif not args.gpiotest:
        log("GPIO checks skipped: built without libgpiod 2 (libgpiod-dev >= 2 and libgpiod.a "
            "not found; Debian 12: bookworm-backports)")
    runs = []
    if args.only in (None, "std"):
        wanted = ["bochs", "vfb"] + (["configfs", "gpio_sim"] if gpio else [])
        runs.append(dict(name="std", vga="std", modules=module_order(index, wanted), vfb=True,
                         gpio=gpio))
    if args.only in (None, "cirrus"):
        runs.append(dict(name="cirrus", vga="cirrus", modules=module_order(index, ["cirrus"]),
                         vfb=False))
    if args.only in (None, "vesa"):
        # vesafb is built in: no modules; 0x318 = 1024x768, 24 bpp
        runs.append(dict(name="vesa", vga="std", modules=[], vfb=False, append="vga=0x318"))
    # the guests are independent: boot as many at once as there are cores
    jobs = max(1, min(len(runs), args.jobs or (os.cpu_count() or 1)))
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(boot, args, kernel=kernel, index=index, work=args.work, **r)
                   for r in runs]
        for f in futures:
            ok &= f.result()
    log("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
