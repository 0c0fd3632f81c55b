#!/usr/bin/env python3
"""Independent Dynamixel Protocol 2.0 master (Python 3 standard library only), written from the published
protocol, not from this code base. It talks to a bus on a serial device (e.g. the pty of `robotctl bus-sim --pty`)
and checks that every instruction answers as the protocol says, that each error case gets its protocol error code,
and that no command is silently dropped.

usage: dxl_master.py /dev/pts/N      (the modules at 1 Mbaud, their factory baud)
Exit status 0 when every check passed; one line per check on stdout."""
import os
import select
import struct
import sys
import termios
import time

# Control-table addresses (docs/protocol.md): the Dynamixel-standard ones and the module's feedback block.
MODEL, FW, ID, RDELAY = 0, 6, 7, 9
MOTOR_COUNT, KP, POS_MAX, POT_POS0 = 2, 20, 32, 36
TORQUE, HW_ERROR, RESET_CAUSE, WATCHDOG, GOAL, PRESENT, HOME, WATCHDOG_OFF = 224, 228, 229, 230, 232, 248, 324, 326
CLEAR_KEY = bytes([0x44, 0x58, 0x4C, 0x22])


def crc16(data, crc=0):
    """CRC-16 of the protocol: polynomial 0x8005, initial value 0, MSB first."""
    for b in data:
        crc ^= b << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x8005) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc


def stuff(body):
    out = bytearray()
    for i, b in enumerate(body):
        out.append(b)
        if b == 0xFD and i >= 2 and body[i - 1] == 0xFF and body[i - 2] == 0xFF:
            out.append(0xFD)
    return bytes(out)


def packet(ident, inst, params=b""):
    """An instruction packet (or, with inst 0x55 and the error byte first in params, a status packet)."""
    body = stuff(bytes([inst]) + params)
    head = bytes([0xFF, 0xFF, 0xFD, 0x00, ident]) + struct.pack("<H", len(body) + 2) + body
    return head + struct.pack("<H", crc16(head))


class Bus:
    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        attrs = termios.tcgetattr(self.fd)
        attrs[0] = attrs[1] = attrs[3] = 0  # raw: no input/output/local processing
        attrs[2] = termios.CS8 | termios.CREAD | termios.CLOCAL
        attrs[4] = attrs[5] = termios.B1000000  # the modules' factory baud
        attrs[6][termios.VMIN] = 0
        attrs[6][termios.VTIME] = 0
        termios.tcsetattr(self.fd, termios.TCSANOW, attrs)
        self.buf = bytearray()

    def send(self, ident, inst, params=b""):
        self.drain()
        os.write(self.fd, packet(ident, inst, params))

    def drain(self):
        while select.select([self.fd], [], [], 0.02)[0]:
            if not os.read(self.fd, 4096):
                break
        self.buf.clear()

    def fill(self, deadline):
        left = deadline - time.monotonic()
        if left > 0 and select.select([self.fd], [], [], left)[0]:
            self.buf += os.read(self.fd, 4096)
            return True
        return False

    def status(self, timeout=0.5):
        """Next status packet: (id, error, data), or None on timeout. Unstuffs; drops bad CRCs."""
        deadline = time.monotonic() + timeout
        while True:
            at = self.buf.find(b"\xFF\xFF\xFD\x00")
            if at >= 0 and len(self.buf) >= at + 7:
                length = struct.unpack_from("<H", self.buf, at + 5)[0]
                end = at + 7 + length
                if len(self.buf) >= end:
                    raw = bytes(self.buf[at:end])
                    del self.buf[:end]
                    if crc16(raw[:-2]) != struct.unpack_from("<H", raw, len(raw) - 2)[0]:
                        continue
                    body = raw[7:-2].replace(b"\xFF\xFF\xFD\xFD", b"\xFF\xFF\xFD")
                    if body[0] != 0x55:
                        continue
                    return raw[4], body[1], body[2:]
            if not self.fill(deadline):
                return None

    def raw(self, count, timeout=0.5):
        deadline = time.monotonic() + timeout
        while len(self.buf) < count and self.fill(deadline):
            pass
        out = bytes(self.buf[:count])
        del self.buf[:count]
        return out


class Checks:
    def __init__(self):
        self.failed = 0

    def check(self, name, ok, detail=""):
        print("%s %s%s" % ("ok  " if ok else "FAIL", name, "" if ok else ": " + detail))
        self.failed += 0 if ok else 1


def rd(a, n):
    return struct.pack("<HH", a, n)


def wr(a, data):
    return struct.pack("<H", a) + data


def main():
    path = sys.argv[1]
    bus, c = Bus(path), Checks()

    # Broadcast ping: every module answers.
    bus.send(0xFE, 0x01)
    found = []
    while True:
        st = bus.status(0.3)
        if st is None:
            break
        found.append(st)
    c.check("broadcast ping answered", len(found) >= 2, "%d modules" % len(found))
    ids = sorted(s[0] for s in found)
    a, b = ids[0], ids[1]
    model = struct.unpack("<H", found[0][2][:2])[0]

    def ask(ident, inst, params=b""):
        bus.send(ident, inst, params)
        return bus.status()

    def expect(name, ident, inst, params, error, data=None):
        st = ask(ident, inst, params)
        ok = st is not None and st[0] == ident and st[1] & 0x7F == error and (data is None or st[2] == data)
        c.check(name, ok, "got %r, expected error 0x%02X" % (st, error))
        return st

    st = expect("ping", a, 0x01, b"", 0)
    expect("read model number", a, 0x02, rd(MODEL, 2), 0, struct.pack("<H", model))
    # Error codes, as the protocol defines them.
    expect("0x02 undefined instruction", a, 0x20, b"", 0x02)
    expect("0x04 value out of range (id 253)", a, 0x03, wr(ID, b"\xFD"), 0x04)
    expect("0x05 write shorter than the field", a, 0x03, wr(KP, b"\x01"), 0x05)
    expect("0x05 read with missing parameters", a, 0x02, b"\x00\x00\x02", 0x05)
    pmax = struct.unpack("<i", expect("read position_max", a, 0x02, rd(POS_MAX, 4), 0)[2])[0]
    expect("0x06 goal beyond the configured limit", a, 0x03, wr(GOAL, struct.pack("<i", pmax + 1)), 0x06)
    expect("0x07 write to a read-only field", a, 0x03, wr(MODEL, b"\x00\x00"), 0x07)
    # A refused read carries the requested length of zero bytes, as a ROBOTIS device answers.
    expect("0x07 read of an unmapped byte, with its length of zeros", a, 0x02, rd(3, 1), 0x07, b"\x00")
    expect("0x07 read past the table, with its length of zeros", a, 0x02, rd(0xFFF0, 4), 0x07, bytes(4))
    delay = expect("read return delay", a, 0x02, rd(RDELAY, 1), 0)[2]
    expect("torque on", a, 0x03, wr(TORQUE, b"\x01"), 0)
    expect("0x07 persistent-area write while torque is on", a, 0x03, wr(RDELAY, delay), 0x07)
    expect("torque off", a, 0x03, wr(TORQUE, b"\x00"), 0)
    expect("persistent-area write with torque off", a, 0x03, wr(RDELAY, delay), 0)

    # REG WRITE + ACTION: registered, not applied, then applied.
    goal = expect("read goal", a, 0x02, rd(GOAL, 4), 0)[2]
    new_goal = struct.pack("<i", struct.unpack("<i", goal)[0] + 3)
    expect("reg write", a, 0x04, wr(GOAL, new_goal), 0)
    expect("reg write not applied yet", a, 0x02, rd(GOAL, 4), 0, goal)
    expect("action", a, 0x05, b"", 0)
    expect("action applied the registered write", a, 0x02, rd(GOAL, 4), 0, new_goal)
    expect("action with nothing registered: instruction error", a, 0x05, b"", 0x02)
    expect("clear errors", a, 0x10, b"\x02" + CLEAR_KEY, 0)
    expect("clear multi-turn does not apply: result fail", a, 0x10, b"\x01" + CLEAR_KEY, 0x01)
    expect("clear with a wrong key: data range", a, 0x10, b"\x02\x00\x00\x00\x00", 0x04)

    # More error cases: each gets its own code.
    expect("0x07 write to an unmapped byte", a, 0x03, wr(3, b"\x00"), 0x07)
    expect("0x07 write past the table", a, 0x03, wr(0xFFF0, b"\x00"), 0x07)
    expect("0x05 reg write without data", a, 0x04, struct.pack("<H", GOAL), 0x05)
    expect("0x05 action with parameters", a, 0x05, b"\x00", 0x05)
    expect("0x05 clear without its key", a, 0x10, b"\x02", 0x05)
    expect("0x05 factory reset without a mode", a, 0x06, b"", 0x05)
    expect("0x04 factory reset mode not defined", a, 0x06, b"\x03", 0x04)
    expect("0x04 home_request above its range", a, 0x03, wr(HOME, b"\x10"), 0x04)
    expect("torque on (motor 0)", a, 0x03, wr(TORQUE, b"\x01"), 0)
    expect("0x01 homing a driven motor is refused", a, 0x03, wr(HOME, b"\x01"), 0x01)
    expect("torque off (motor 0)", a, 0x03, wr(TORQUE, b"\x00"), 0)

    # Byte stuffing both ways: a request whose parameters hold FF FF FD (a READ of address FFFF, length 00FD: past the
    # table, so 0x07; read unstuffed it would have 5 parameters, 0x05), and a reply whose data holds it.
    expect("stuffed request is unstuffed (0x07, not 0x05)", a, 0x02, rd(0xFFFF, 0x00FD), 0x07)
    pos0 = expect("read pot_cal_pos0", a, 0x02, rd(POT_POS0, 4), 0)[2]
    expect("write FF FF FD FF (stuffed request)", a, 0x03, wr(POT_POS0, b"\xFF\xFF\xFD\xFF"), 0)
    bus.send(a, 0x02, rd(POT_POS0, 4))
    want = packet(a, 0x55, b"\x00\xFF\xFF\xFD\xFF")
    got = bus.raw(len(want))
    c.check("reply data FF FF FD FF comes stuffed (FF FF FD FD FF)", got == want, got.hex(" "))
    expect("restore pot_cal_pos0", a, 0x03, wr(POT_POS0, pos0), 0)

    # Alerts: a latched error (bus watchdog expired) sets bit 7 of every status error byte until it is cleared.
    expect("bus watchdog 20 ms", a, 0x03, wr(WATCHDOG, struct.pack("<H", 20)), 0)
    time.sleep(0.3)
    st = ask(a, 0x01)
    c.check("alert bit set once the watchdog expired", st is not None and st[1] == 0x80, repr(st))
    expect("0x01 torque on while the watchdog error is latched", a, 0x03, wr(TORQUE, b"\x01"), 0x01)
    expect("bus watchdog off", a, 0x03, wr(WATCHDOG, b"\x00\x00"), 0)
    expect("clear errors", a, 0x10, b"\x02" + CLEAR_KEY, 0)
    st = ask(a, 0x01)
    c.check("alert bit gone after clear", st is not None and st[1] == 0x00, repr(st))

    # The watchdog's two stages (firmware 3): the second must come after the first (so it is written first: with the
    # second stage 0, the first alone would switch the motors off); a short silence is a hold (bit 6) that refuses
    # goals until the host clears the error status.
    expect("second stage 2000 ms", a, 0x03, wr(WATCHDOG_OFF, struct.pack("<H", 2000)), 0)
    expect("0x06 first stage not before the second", a, 0x03, wr(WATCHDOG, struct.pack("<H", 2000)), 0x06)
    expect("bus watchdog 20 ms", a, 0x03, wr(WATCHDOG, struct.pack("<H", 20)), 0)
    time.sleep(0.3)
    st = expect("read the error status after a silence", a, 0x02, rd(HW_ERROR, 1), 0)
    c.check("hold bit set, alert set, not tripped", st is not None and st[1] == 0x80 and st[2] == b"\x40", repr(st))
    held = expect("read the held goal", a, 0x02, rd(GOAL, 4), 0)[2]
    expect("0x01 goal while holding", a, 0x03, wr(GOAL, held), 0x01)
    expect("bus watchdog off", a, 0x03, wr(WATCHDOG, b"\x00\x00"), 0)
    expect("clear errors (acknowledges the hold)", a, 0x03, wr(HW_ERROR, b"\x00"), 0)
    expect("goal after the acknowledgement", a, 0x03, wr(GOAL, held), 0)
    expect("second stage 0 (no hold stage)", a, 0x03, wr(WATCHDOG_OFF, b"\x00\x00"), 0)

    # REG WRITE in two modules, one broadcast ACTION: no reply, both applied.
    goal_a = expect("read goal", a, 0x02, rd(GOAL, 4), 0)[2]
    goal_b = expect("read goal (second module)", b, 0x02, rd(GOAL, 4), 0)[2]
    ra = struct.pack("<i", struct.unpack("<i", goal_a)[0] + 2)
    rb = struct.pack("<i", struct.unpack("<i", goal_b)[0] + 2)
    expect("reg write (first module)", a, 0x04, wr(GOAL, ra), 0)
    expect("reg write (second module)", b, 0x04, wr(GOAL, rb), 0)
    bus.send(0xFE, 0x05)
    c.check("broadcast action: no reply", bus.status(0.1) is None)
    expect("broadcast action applied (first module)", a, 0x02, rd(GOAL, 4), 0, ra)
    expect("broadcast action applied (second module)", b, 0x02, rd(GOAL, 4), 0, rb)

    # SYNC WRITE is applied in every listed module, with no reply.
    sa = struct.pack("<i", struct.unpack("<i", ra)[0] - 1)
    sb = struct.pack("<i", struct.unpack("<i", rb)[0] - 1)
    bus.send(0xFE, 0x83, rd(GOAL, 4) + bytes([a]) + sa + bytes([b]) + sb)
    c.check("sync write: no reply", bus.status(0.1) is None)
    expect("sync write applied (first module)", a, 0x02, rd(GOAL, 4), 0, sa)
    expect("sync write applied (second module)", b, 0x02, rd(GOAL, 4), 0, sb)
    new_goal = sa

    # BULK WRITE is applied (never silently dropped), BULK READ answers in list order.
    goal_b = expect("read goal (second module)", b, 0x02, rd(GOAL, 4), 0)[2]
    ga = struct.pack("<i", struct.unpack("<i", new_goal)[0] - 1)
    gb = struct.pack("<i", struct.unpack("<i", goal_b)[0] + 1)
    bus.send(0xFE, 0x93, bytes([a]) + rd(GOAL, 4) + ga + bytes([b]) + rd(GOAL, 4) + gb)
    c.check("bulk write: no reply", bus.status(0.1) is None)
    expect("bulk write applied (first module)", a, 0x02, rd(GOAL, 4), 0, ga)
    expect("bulk write applied (second module)", b, 0x02, rd(GOAL, 4), 0, gb)
    bus.send(0xFE, 0x92, bytes([b]) + rd(GOAL, 4) + bytes([a]) + rd(MODEL, 2))
    r1, r2 = bus.status(), bus.status()
    c.check("bulk read answers in list order", r1 is not None and r2 is not None and (r1[0], r2[0]) == (b, a)
            and r1[2] == gb and r2[2] == struct.pack("<H", model), "%r %r" % (r1, r2))
    bus.send(0xFE, 0x82, rd(PRESENT, 8) + bytes(ids))
    got = [bus.status() for _ in ids]
    c.check("sync read: every module, in list order", [g[0] if g else None for g in got] == ids, repr(got))

    # FAST SYNC READ / FAST BULK READ: one packet from ID 0xFE, a CRC after every module's part.
    for name, inst, params, lengths in (
            ("fast sync read", 0x8A, rd(GOAL, 4) + bytes([a, b]), [4, 4]),
            ("fast bulk read", 0x9A, bytes([a]) + rd(GOAL, 4) + bytes([b]) + rd(MODEL, 2), [4, 2])):
        bus.send(0xFE, inst, params)
        size = 8 + sum(4 + n for n in lengths)
        pk = bus.raw(size)
        ok = len(pk) == size and pk[:5] == b"\xFF\xFF\xFD\x00\xFE" and pk[7] == 0x55
        ok = ok and struct.unpack_from("<H", pk, 5)[0] == size - 7
        at = 8
        for ident, n in zip((a, b), lengths):
            ok = ok and pk[at] & 0x7F == 0 and pk[at + 1] == ident
            ok = ok and crc16(pk[:at + 2 + n]) == struct.unpack_from("<H", pk, at + 2 + n)[0]
            at += 4 + n
        c.check(name + ": one packet, each part with its CRC", ok, pk.hex(" "))
        c.check(name + ": data", ok and pk[10:14] == ga, pk.hex(" "))

    # REBOOT and FACTORY RESET answer before they act; the module is back afterwards.
    expect("reboot", b, 0x08, b"", 0)
    time.sleep(0.2)
    expect("after the reboot: reset cause 4 (software)", b, 0x02, rd(RESET_CAUSE, 1), 0, b"\x04")
    expect("kp set away from its default", b, 0x03, wr(KP, struct.pack("<H", 300)), 0)
    expect("factory reset (all but ID and baud)", b, 0x06, b"\x02", 0)
    time.sleep(0.2)
    expect("after the factory reset: kp back at its default 256, same ID and baud", b, 0x02, rd(KP, 2), 0, struct.pack("<H", 256))

    print("%d failed" % c.failed)
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())
