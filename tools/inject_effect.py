#!/usr/bin/python3
"""Put a known physical effect into a recorded dataset (a real log), so that
`sinu diagnose` can be tried on data our simulator did not make.

  /usr/bin/python3 tools/inject_effect.py --in ../shared/data/real/uav_log171 \
      --effects effects.json --nav NAV.csv --out /tmp/uav_gyro_scale

effects.json is the simulator's effects object (docs: firmware/host/sim/effects.hpp;
`sinu simulate flight --hidden-out` writes one under "effects"), applied to the
recorded measurements as the simulator applies it to the true ones:
  accel: a' = (I + diag(s)) (I + M) a + k (T - 25 degC)
  gyro:  w' = (I + diag(s)) (I + M) w + G a + k (T - 25 degC)
  mag:   m' = S R m + b + k (-a_z - g0)   (S the soft iron, R = exp(-[theta x]) the misalignment,
                               b the hard iron, k the motors' field against the thrust)
  lever_arm l:    every fix moves to the antenna: p + C_nb l, v + C_nb (w x l)
  gps_latency dt: every sentence arrives dt later (its UTC still the fix's instant,
                  as the dataset contract says; a real receiver's latency)
  mag_latency tau: every field sample is the log's own field tau earlier (interpolated
                  between its samples; none before the first tau of field)
  gps_velocity_latency tau: every RMC/VTG velocity is the log's own velocity tau
                  earlier (interpolated between its epochs), on top of its own lag
The recording's own errors stay in (the log's unit has its own scale factors,
lever arm, ...): compare with a diagnosis of the untouched log, or start from
its model file. --nav gives the attitude for the lever arm (a `sinu replay`
nav.csv, or truth.csv with roll, pitch, yaw); the rest needs none.
Empty fields stay empty; truth.csv is not copied (diagnose runs without it).
"""
import argparse
import bisect
import csv
import json
import math
import os
import shutil

import numpy as np

TEMP_REFERENCE_DEGC = 25.0
STANDARD_GRAVITY = 9.80665  # g0 [m/s^2]: the motors' field is against the thrust beyond it
WGS84_A, WGS84_E2 = 6378137.0, 6.69437999014e-3


def rotation_nb(roll_deg, pitch_deg, yaw_deg):
    """C_nb from ZYX Euler angles (body FRD to NED)."""
    r, p, y = (math.radians(v) for v in (roll_deg, pitch_deg, yaw_deg))
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return np.array([[cp * cy, sr * sp * cy - cr * sy, cr * sp * cy + sr * sy],
                     [cp * sy, sr * sp * sy + cr * cy, cr * sp * sy - sr * cy],
                     [-sp, sr * cp, cr * cp]])


def matrix(v):
    return np.array(v, dtype=float).reshape(3, 3)


def mag_axes(theta):
    """The magnetometer's axes turned by theta [rad]: exp(-[theta x]) (Rodrigues)."""
    angle = np.linalg.norm(theta)
    if angle == 0.0:
        return np.eye(3)
    k = theta / angle
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) - math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def imu_transform(fx):
    """The effects on (a, w, m, temp) -> (a', w', m')."""
    eye = np.eye(3)
    acc = (eye + np.diag(np.array(fx.get("accel_scale", [0, 0, 0])) * 1e-6)) @ (
        eye + matrix(fx.get("accel_misalign", np.zeros((3, 3)))))
    gyr = (eye + np.diag(np.array(fx.get("gyro_scale", [0, 0, 0])) * 1e-6)) @ (
        eye + matrix(fx.get("gyro_misalign", np.zeros((3, 3)))))
    g_sens = matrix(fx.get("gyro_g_sensitivity", np.zeros((3, 3))))
    acc_k = np.array(fx.get("accel_temp_bias", [0, 0, 0]), dtype=float)
    gyr_k = np.array(fx.get("gyro_temp_bias", [0, 0, 0]), dtype=float)
    soft = matrix(fx.get("mag_soft_iron", np.eye(3))) @ mag_axes(np.array(fx.get("mag_misalign", [0, 0, 0]), float))
    hard = np.array(fx.get("mag_hard_iron", [0, 0, 0]), dtype=float)
    motor = np.array(fx.get("mag_motor_interference", [0, 0, 0]), dtype=float)
    needs_temp = bool(acc_k.any() or gyr_k.any())

    def apply(a, w, m, temp):
        dT = (temp - TEMP_REFERENCE_DEGC) if temp is not None else None
        if needs_temp and dT is None:
            raise SystemExit("inject_effect: a temperature coefficient needs the temp column, and the first rows have none")
        a2 = w2 = m2 = None
        if a is not None:
            a2 = acc @ a + (acc_k * dT if needs_temp else 0.0)
        if w is not None:
            w2 = gyr @ w + (g_sens @ a if a is not None else 0.0) + (gyr_k * dT if needs_temp else 0.0)
        if m is not None:
            if motor.any() and a is None:
                raise SystemExit("inject_effect: mag_motor_interference needs the accelerometer on every field row")
            m2 = soft @ m + hard + (motor * (-a[2] - STANDARD_GRAVITY) if motor.any() else 0.0)
        return a2, w2, m2

    return apply


def triple(row, keys, where):
    vals = [row[k].strip() for k in keys]
    if all(v == "" for v in vals):
        return None
    if any(v == "" for v in vals):
        raise SystemExit(f"inject_effect: {where}: {'/'.join(keys)} partly empty")
    return np.array([float(v) for v in vals])


def inject_imu(src, dst, fx):
    """imu.csv through the effects; returns (t, gyro) for the lever arm's rotation."""
    apply = imu_transform(fx)
    times, rates = [], []
    temp = None
    with open(src, newline="") as fi, open(dst, "w", newline="") as fo:
        header = fi.readline()
        fo.write(header)
        names = header.strip().split(",")
        for n, line in enumerate(fi, start=2):
            row = dict(zip(names, line.rstrip("\r\n").split(",")))
            where = f"{src}:{n}"
            if row.get("temp", "").strip():
                temp = float(row["temp"])
            a = triple(row, ("ax", "ay", "az"), where)
            w = triple(row, ("gx", "gy", "gz"), where)
            m = triple(row, ("mx", "my", "mz"), where)
            a2, w2, m2 = apply(a, w, m, temp)
            if w is not None:
                times.append(float(row["t"]))
                rates.append(w)

            def fmt(v):
                return ["", "", ""] if v is None else [f"{x:.9g}" for x in v]

            fo.write(",".join([row["t"]] + fmt(a2) + fmt(w2) + fmt(m2) + [row.get("temp", "")]) + "\n")
    return np.array(times), np.array(rates)


# --- NMEA ---------------------------------------------------------------------------------------

def checksum(body):
    c = 0
    for ch in body:
        c ^= ord(ch)
    return f"{c:02X}"


def split_sentence(s):
    """'$GPGGA,...*hh' -> (fields, True) or (None, False) when it is not a valid sentence."""
    if not s.startswith("$") or "*" not in s:
        return None, False
    body, _, cs = s[1:].partition("*")
    if checksum(body) != cs.strip()[:2].upper():
        return None, False
    return body.split(","), True


def join_sentence(fields):
    body = ",".join(fields)
    return f"${body}*{checksum(body)}"


def utc_seconds(hhmmss):
    if len(hhmmss) < 6:
        return None
    return int(hhmmss[0:2]) * 3600 + int(hhmmss[2:4]) * 60 + float(hhmmss[4:])


def decimals(s):
    return len(s.split(".")[1]) if "." in s else 0


def parse_lat(v, hemi):
    deg = int(float(v) / 100)
    x = deg + (float(v) - 100 * deg) / 60.0
    return -x if hemi in ("S", "W") else x


def format_angle(x, width_deg, template):
    """Degrees -> NMEA ddmm.mmmm (or dddmm.mmmm) with the template's decimals, and its hemisphere sign."""
    a = abs(x)
    deg = int(a)
    minutes = (a - deg) * 60.0
    d = decimals(template)
    minutes = round(minutes, d)
    if minutes >= 60.0:
        deg, minutes = deg + 1, minutes - 60.0
    return f"{deg:0{width_deg}d}{minutes:0{3 + d if d else 2}.{d}f}"


class Attitude:
    """C_nb at a board time, from a nav.csv or truth.csv (t, roll, pitch, yaw [deg])."""

    def __init__(self, path):
        self.t, self.rpy = [], []
        for r in csv.DictReader(open(path, newline="")):
            if r.get("roll", "") and r.get("pitch", "") and r.get("yaw", ""):
                self.t.append(float(r["t"]))
                self.rpy.append((float(r["roll"]), float(r["pitch"]), float(r["yaw"])))
        if not self.t:
            raise SystemExit(f"inject_effect: {path}: no row with roll, pitch and yaw")

    def C_nb(self, t):
        i = min(bisect.bisect_left(self.t, t), len(self.t) - 1)
        return rotation_nb(*self.rpy[i])


def shift(lat, lon, alt, d_ned):
    """Position moved by d_ned [m]."""
    s = math.sin(math.radians(lat))
    rn = WGS84_A / math.sqrt(1 - WGS84_E2 * s * s)
    rm = rn * (1 - WGS84_E2) / (1 - WGS84_E2 * s * s)
    return (lat + math.degrees(d_ned[0] / (rm + alt)),
            lon + math.degrees(d_ned[1] / ((rn + alt) * math.cos(math.radians(lat)))), alt - d_ned[2])


def own_position(f, kind, ilat):
    """(lat, lon, alt) of a GGA/RMC/GLL sentence (alt 0 where it has none), or None."""
    try:
        if ilat is None or not f[ilat] or not f[ilat + 2]:
            return None
        alt = float(f[9]) if kind == "GGA" and f[9] else 0.0
        return parse_lat(f[ilat], f[ilat + 1]), parse_lat(f[ilat + 2], f[ilat + 3]), alt
    except (ValueError, IndexError):
        return None


def own_velocity(f, ispeed, icourse):
    """(vn, ve) [m/s] of an RMC/VTG sentence, or None."""
    try:
        if ispeed is None or not f[ispeed]:
            return None
        sp = float(f[ispeed]) * 1852.0 / 3600.0
        course = math.radians(float(f[icourse])) if f[icourse] else 0.0
        return sp * math.cos(course), sp * math.sin(course)
    except (ValueError, IndexError):
        return None


def arrival_text(arrival, latency):
    """The arrival time `latency` later, with the original's decimals (at least milliseconds)."""
    if not latency:
        return arrival
    return f"{float(arrival) + latency:.{max(3, decimals(arrival))}f}"


# Where a sentence carries its speed [knots] and course: RMC fields 7, 8; VTG 5, 1.
VELOCITY_FIELDS = {"RMC": (7, 8), "VTG": (5, 1)}


def velocity_series(src):
    """(arrival times, vn, ve) of the log's RMC/VTG velocities, for the velocity's lag."""
    t, vn, ve = [], [], []
    with open(src, newline="") as fi:
        for raw in fi:
            arrival, _, s = raw.rstrip("\r\n").partition(",")
            f, ok = split_sentence(s)
            kind = f[0][2:] if ok else ""
            ispeed, icourse = VELOCITY_FIELDS.get(kind, (None, None))
            vel = own_velocity(f, ispeed, icourse) if ok else None
            if vel is not None and (not t or float(arrival) > t[-1]):
                t.append(float(arrival))
                vn.append(vel[0])
                ve.append(vel[1])
    return np.array(t), np.array(vn), np.array(ve)


def inject_gps(src, dst, fx, attitude, imu_t, imu_w):
    latency = float(fx.get("gps_latency", 0.0))
    tau = float(fx.get("gps_velocity_latency", 0.0))
    lever = np.array(fx["lever_arm"], dtype=float) if "lever_arm" in fx else None
    if lever is not None and attitude is None:
        raise SystemExit("inject_effect: lever_arm needs --nav (a nav.csv or truth.csv with roll, pitch, yaw)")
    series = velocity_series(src) if tau else None
    with open(src, newline="") as fi, open(dst, "w", newline="") as fo:
        for raw in fi:
            arrival, _, s = raw.rstrip("\r\n").partition(",")
            f, ok = split_sentence(s)
            kind = f[0][2:] if ok else ""
            if (lever is None and not tau) or kind not in ("GGA", "RMC", "GLL", "VTG"):
                fo.write(f"{arrival_text(arrival, latency)},{s}\n")
                continue
            f = list(f)
            ilat = {"GGA": 2, "RMC": 3, "GLL": 1}.get(kind)
            ispeed, icourse = VELOCITY_FIELDS.get(kind, (None, None))
            pos, vel = own_position(f, kind, ilat), own_velocity(f, ispeed, icourse)
            if tau and vel is not None and len(series[0]) > 1:
                at = float(arrival) - tau
                vel = (float(np.interp(at, series[0], series[1])), float(np.interp(at, series[0], series[2])))
            if lever is None:
                pos, dv = None, np.zeros(3)
            else:
                C = attitude.C_nb(float(arrival))
            if pos is not None:
                pos = shift(*pos, C @ lever)
                f[ilat] = format_angle(pos[0], 2, f[ilat])
                f[ilat + 1] = "S" if pos[0] < 0 else "N"
                f[ilat + 2] = format_angle(pos[1], 3, f[ilat + 2])
                f[ilat + 3] = "W" if pos[1] < 0 else "E"
                if kind == "GGA" and f[9]:
                    f[9] = f"{pos[2]:.{decimals(f[9])}f}"
            if vel is not None and len(imu_t):
                if lever is not None:
                    w = imu_w[min(bisect.bisect_left(imu_t, float(arrival)), len(imu_t) - 1)]
                    dv = C @ np.cross(w, lever)
                vn, ve = vel[0] + dv[0], vel[1] + dv[1]
                sp = math.hypot(vn, ve)
                f[ispeed] = f"{sp * 3600.0 / 1852.0:.{decimals(f[ispeed])}f}"
                if f[icourse]:
                    f[icourse] = f"{math.degrees(math.atan2(ve, vn)) % 360.0:.{decimals(f[icourse])}f}"
                if kind == "VTG" and len(f) > 7 and f[7]:
                    f[7] = f"{sp * 3.6:.{decimals(f[7])}f}"
            fo.write(f"{arrival_text(arrival, latency)},{join_sentence(f)}\n")


def delay_field(path, tau):
    """imu.csv's field samples replaced by the field tau earlier (mag_latency)."""
    with open(path, newline="") as f:
        header = f.readline()
        rows = [line.rstrip("\r\n").split(",") for line in f]
    names = header.strip().split(",")
    it, ix = names.index("t"), names.index("mx")
    field_t = np.array([float(r[it]) for r in rows if r[ix].strip()])
    field = np.array([[float(v) for v in r[ix:ix + 3]] for r in rows if r[ix].strip()])
    with open(path, "w", newline="") as f:
        f.write(header)
        for r in rows:
            if r[ix].strip():
                t = float(r[it]) - tau
                r[ix:ix + 3] = ([f"{np.interp(t, field_t, field[:, k]):.9g}" for k in range(3)]
                                if t >= field_t[0] else ["", "", ""])
            f.write(",".join(r) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--in", dest="src", required=True, help="dataset folder (imu.csv, gps.nmea)")
    ap.add_argument("--effects", required=True, help="effects JSON (the simulator's effects object)")
    ap.add_argument("--nav", help="nav.csv or truth.csv with roll, pitch, yaw (needed by lever_arm)")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    try:
        fx = json.load(open(a.effects))
    except (OSError, ValueError) as e:
        raise SystemExit(f"inject_effect: {a.effects}: {e}")
    if not isinstance(fx, dict):
        raise SystemExit(f"inject_effect: {a.effects}: expected a JSON object of effects")
    fx = fx.get("effects", fx)
    known = {"accel_scale", "gyro_scale", "accel_misalign", "gyro_misalign", "gyro_g_sensitivity", "accel_temp_bias",
             "gyro_temp_bias", "mag_soft_iron", "mag_hard_iron", "mag_misalign", "lever_arm", "gps_latency",
             "gps_velocity_latency", "mag_motor_interference", "mag_latency"}
    unknown = set(fx) - known
    if unknown:
        raise SystemExit(f"inject_effect: {a.effects}: unknown effect(s) {', '.join(sorted(unknown))}")
    os.makedirs(a.out, exist_ok=True)
    imu_t, imu_w = inject_imu(os.path.join(a.src, "imu.csv"), os.path.join(a.out, "imu.csv"), fx)
    if float(fx.get("mag_latency", 0.0)) > 0.0:
        delay_field(os.path.join(a.out, "imu.csv"), float(fx["mag_latency"]))
    gps = os.path.join(a.src, "gps.nmea")
    if os.path.exists(gps):
        inject_gps(gps, os.path.join(a.out, "gps.nmea"), fx, Attitude(a.nav) if a.nav else None, imu_t, imu_w)
    if os.path.exists(os.path.join(a.src, "meta.json")):
        shutil.copy(os.path.join(a.src, "meta.json"), os.path.join(a.out, "meta.json"))
    json.dump({"effects": fx, "source": os.path.abspath(a.src)}, open(os.path.join(a.out, "injected.json"), "w"),
              indent=2)


if __name__ == "__main__":
    main()
