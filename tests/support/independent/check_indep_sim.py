#!/usr/bin/env python3
"""Sanity checks of reckoner-indep-sim output (standard library only).

usage: check_indep_sim.py DIR [DIR...]   (each DIR written by `ownship` or `arpa`)

Checks: every NMEA line's framing and checksum, ZDA first in each second, no GNSS in the outage;
the truth track's continuity, speed and turn limits; sensor error statistics against params.json;
for `arpa`, each target's CPA/TCPA at t0 recomputed from truth_targets.csv. Geodesy here is
Vincenty's inverse formula, independent of the GeographicLib the generator uses.
Exit status 1 on any failure.
"""
import csv, json, math, re, statistics, sys
from collections import Counter, defaultdict

A, F = 6378137.0, 1 / 298.257223563
B = A * (1 - F)
KN = 1852.0 / 3600.0
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
    return cond


def inverse(lat1, lon1, lat2, lon2):
    """Vincenty inverse on WGS-84: (distance m, initial azimuth deg)."""
    L = math.radians(lon2 - lon1)
    U1, U2 = math.atan((1 - F) * math.tan(math.radians(lat1))), math.atan((1 - F) * math.tan(math.radians(lat2)))
    sU1, cU1, sU2, cU2 = math.sin(U1), math.cos(U1), math.sin(U2), math.cos(U2)
    lam = L
    for _ in range(200):
        sl, cl = math.sin(lam), math.cos(lam)
        ss = math.hypot(cU2 * sl, cU1 * sU2 - sU1 * cU2 * cl)
        if ss == 0:
            return 0.0, 0.0
        cs = sU1 * sU2 + cU1 * cU2 * cl
        sig = math.atan2(ss, cs)
        sa = cU1 * cU2 * sl / ss
        c2a = 1 - sa * sa
        c2sm = cs - 2 * sU1 * sU2 / c2a if c2a else 0.0
        C = F / 16 * c2a * (4 + F * (4 - 3 * c2a))
        prev, lam = lam, L + (1 - C) * F * sa * (sig + C * ss * (c2sm + C * cs * (-1 + 2 * c2sm * c2sm)))
        if abs(lam - prev) < 1e-13:
            break
    u2 = c2a * (A * A - B * B) / (B * B)
    Ak = 1 + u2 / 16384 * (4096 + u2 * (-768 + u2 * (320 - 175 * u2)))
    Bk = u2 / 1024 * (256 + u2 * (-128 + u2 * (74 - 47 * u2)))
    ds = Bk * ss * (c2sm + Bk / 4 * (cs * (-1 + 2 * c2sm * c2sm) - Bk / 6 * c2sm * (-3 + 4 * ss * ss) * (-3 + 4 * c2sm * c2sm)))
    az = math.degrees(math.atan2(cU2 * math.sin(lam), cU1 * sU2 - sU1 * cU2 * math.cos(lam))) % 360.0
    return B * Ak * (sig - ds), az


def enu(lat0, lon0, lat, lon):
    d, az = inverse(lat0, lon0, lat, lon)
    return d * math.sin(math.radians(az)), d * math.cos(math.radians(az))


def ecef(lat, lon):
    la, lo = math.radians(lat), math.radians(lon)
    e2 = F * (2 - F)
    n = A / math.sqrt(1 - e2 * math.sin(la) ** 2)
    return n * math.cos(la) * math.cos(lo), n * math.cos(la) * math.sin(lo), n * (1 - e2) * math.sin(la)


def plane(lat0, lon0):
    """East/north coordinates in the tangent plane at (lat0, lon0), via ECEF (independent of GeographicLib)."""
    o = ecef(lat0, lon0)
    la, lo = math.radians(lat0), math.radians(lon0)
    def f(lat, lon):
        d = [a - b for a, b in zip(ecef(lat, lon), o)]
        e = -math.sin(lo) * d[0] + math.cos(lo) * d[1]
        n = -math.sin(la) * math.cos(lo) * d[0] - math.sin(la) * math.sin(lo) * d[1] + math.cos(la) * d[2]
        return e, n
    return f


def wrap180(x):
    return (x + 180.0) % 360.0 - 180.0


def nmea_deg(value, hemi):
    deg_digits = 2 if hemi in "NS" else 3
    v = int(value[:deg_digits]) + float(value[deg_digits:]) / 60.0
    return -v if hemi in "SW" else v


def read_nmea(path):
    raw = open(path, "rb").read()
    check(raw.endswith(b"\r\n"), f"{path}: last line not CR LF")
    lines = raw.split(b"\r\n")[:-1]
    sentences = []
    for n, line in enumerate(lines, 1):
        text = line.decode("ascii")
        m = re.fullmatch(r"\$([^*$]+)\*([0-9A-F]{2})", text)
        if not check(m, f"{path}:{n}: bad framing {text!r}"):
            continue
        cs = 0
        for ch in m.group(1):
            cs ^= ord(ch)
        check(f"{cs:02X}" == m.group(2), f"{path}:{n}: bad checksum")
        sentences.append(m.group(1).split(","))
    return sentences


def check_ownship_nmea(d, params, truth):
    sens = read_nmea(f"{d}/ownship.nmea")
    print(f"  nmea: {len(sens)} sentences", dict(Counter(s[0] for s in sens)))
    by_t = {int(round(float(r["t_s"]))): r for r in truth}
    t0 = 10 * 3600
    epoch, gyro_err, log_pairs, gnss_err, loran_err, gst_sd = None, [], [], [], [], set()
    for s in sens:
        tag = s[0]
        if tag == "GPZDA":
            check(re.fullmatch(r"\d{6}\.\d{2}", s[1]) and s[3:5] == ["06", "2026"] and s[5:] == ["00", "00"], f"ZDA fields {s}")
            hh, mm, ss = int(s[1][:2]), int(s[1][2:4]), float(s[1][4:])
            day = int(s[2])  # runs start on 2026-06-15; June has 30 days, long runs stay in it
            epoch = int(round((day - 15) * 86400 + hh * 3600 + mm * 60 + ss - t0))
            continue
        check(epoch is not None, f"{tag} before any ZDA")
        row = by_t[epoch]
        if tag in ("GPRMC", "GPGGA", "GPGST", "LCGLL"):
            tf = s[5] if tag == "LCGLL" else s[1]
            check(re.fullmatch(r"\d{6}\.\d{2}", tf), f"{tag} time field {tf}")
            check(abs((int(tf[:2]) * 3600 + int(tf[2:4]) * 60 + float(tf[4:]) - t0) - epoch) % 86400 < 1e-6, f"{tag} time != ZDA")
        if tag.startswith("GP"):
            check(row["gps_on"] == "1", f"GNSS sentence in outage at t={epoch}")
        lat, lon = float(row["lat_deg"]), float(row["lon_deg"])
        if tag == "GPRMC":
            check(s[2] == "A" and s[9] == f"{day:02d}0626" and s[12] == "A", f"RMC fields {s}")
            check(len(s[3].split(".")[1]) == 6 and len(s[5].split(".")[1]) == 6, "RMC lat/lon decimals")
            gnss_err.append(enu(lat, lon, nmea_deg(s[3], s[4]), nmea_deg(s[5], s[6])))
            check(abs(float(s[7]) * KN - float(row["sog_mps"])) < 0.5, f"RMC SOG far from truth at {epoch}")
        elif tag == "GPGGA":
            check(s[6] == "1" and s[7] == "10" and s[8] == "1.0" and len(s) == 15, f"GGA fields {s}")
        elif tag == "GPGST":
            gst_sd.add((s[6], s[7]))
        elif tag == "LCGLL":
            check(s[6] == "A" and s[7] == "A", "GLL status/mode")
            loran_err.append(enu(lat, lon, nmea_deg(s[1], s[2]), nmea_deg(s[3], s[4])))
        elif tag == "HEHDT":
            gyro_err.append(wrap180(float(s[1]) - float(row["heading_deg"])))
        elif tag == "VWVHW":
            check(abs(float(s[7]) - float(s[5]) * 1.852) < 2e-3 and s[6] == "N" and s[8] == "K", f"VHW {s}")
            log_pairs.append((float(row["stw_mps"]) / KN, float(s[5])))
        else:
            check(False, f"unexpected sentence {tag}")
    sp = params["sensors"]
    g = sp["gnss"]
    check(gst_sd == {(f"{g['white_sd_m_per_axis']:.2f}",) * 2}, f"GST sds {gst_sd}")
    if gnss_err:
        sde = statistics.pstdev([e for e, n in gnss_err]); sdn = statistics.pstdev([n for e, n in gnss_err])
        print(f"  gnss: n={len(gnss_err)} error sd east {sde:.2f} north {sdn:.2f} m (expected {g['total_sd_m_per_axis']:.2f})")
        check(abs(sde / g["total_sd_m_per_axis"] - 1) < 0.15 and abs(sdn / g["total_sd_m_per_axis"] - 1) < 0.15, "GNSS sd")
        if g["outage_length_s"] > 0:
            n_out = sum(1 for r in truth if r["gps_on"] == "0")
            check(len(gnss_err) == len(truth) - n_out, "GNSS count vs outage")
    if gyro_err:
        m, sd = statistics.fmean(gyro_err), statistics.pstdev(gyro_err)
        print(f"  gyro: mean error {m:.3f} deg (bias {sp['gyro']['bias_deg']:.3f}), sd {sd:.3f} (expected {sp['gyro']['noise_sd_deg']})")
        check(abs(m - sp["gyro"]["bias_deg"]) < 0.05 and abs(sd / sp["gyro"]["noise_sd_deg"] - 1) < 0.1, "gyro stats")
    if log_pairs:  # measured = (1 + k) stw + o + noise
        xs, ys = [p[0] for p in log_pairs], [p[1] for p in log_pairs]
        res = [y - ((1 + sp["log"]["scale"]) * x + sp["log"]["offset_kn"]) for x, y in log_pairs]
        mres, sdres = statistics.fmean(res), statistics.pstdev(res)
        print(f"  log: residual against the drawn model mean {mres:.4f} kn, sd {sdres:.4f} (noise {sp['log']['noise_sd_kn']})")
        check(abs(mres) < 4 * sp["log"]["noise_sd_kn"] / math.sqrt(len(res)) and abs(sdres / sp["log"]["noise_sd_kn"] - 1) < 0.1, "log model")
        mx, my = statistics.fmean(xs), statistics.fmean(ys)
        sxx = sum((x - mx) ** 2 for x in xs)
        if sxx > 1.0:  # least-squares fit, for information (legs hold few distinct speeds: loose)
            k = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx - 1
            o = my - (1 + k) * mx
            print(f"  log: fitted scale {100*k:.2f}% offset {o:.3f} kn (drawn {sp['log']['scale_percent']:.2f}%, {sp['log']['offset_kn']:.3f} kn)")
    if loran_err:
        sd = math.sqrt(statistics.fmean([e * e + n * n for e, n in loran_err]) / 2)
        print(f"  loran: n={len(loran_err)} rms per axis {sd:.1f} m (model sqrt(150^2+20^2)=151; few correlation times: loose)")
        check(30 < sd < 400, "loran rms")


def check_truth(d, params, arpa):
    truth = list(csv.DictReader(open(f"{d}/truth.csv")))
    check(truth[0]["utc"] == "2026-06-15T10:00:00.000Z", "first utc")
    worst_pos, worst_rate, worst_racc, worst_acc, smin, smax = 0, 0, 0, 0, 1e9, 0
    prev_rate = 0.0
    for a, b in zip(truth, truth[1:]):
        check(abs(float(b["t_s"]) - float(a["t_s"]) - 1.0) < 1e-9, "1 Hz rows")
        dist, _ = inverse(float(a["lat_deg"]), float(a["lon_deg"]), float(b["lat_deg"]), float(b["lon_deg"]))
        expect = 0.5 * (float(a["sog_mps"]) + float(b["sog_mps"]))
        worst_pos = max(worst_pos, abs(dist - expect))
        rate = wrap180(float(b["heading_deg"]) - float(a["heading_deg"]))
        worst_rate = max(worst_rate, abs(rate))
        worst_racc = max(worst_racc, abs(rate - prev_rate)); prev_rate = rate
        worst_acc = max(worst_acc, abs(float(b["stw_mps"]) - float(a["stw_mps"])))
    for r in truth:
        smin, smax = min(smin, float(r["stw_mps"]) / KN), max(smax, float(r["stw_mps"]) / KN)
        ve = float(r["stw_mps"]) * math.sin(math.radians(float(r["heading_deg"]))) + float(r["current_east_mps"])
        vn = float(r["stw_mps"]) * math.cos(math.radians(float(r["heading_deg"]))) + float(r["current_north_mps"])
        check(abs(math.hypot(ve, vn) - float(r["sog_mps"])) < 1e-3, "sog = |water + current|")
    print(f"  truth: {len(truth)} rows; |step - mean sog| <= {worst_pos:.4f} m; turn rate <= {worst_rate:.3f} deg/s; "
          f"turn-rate change <= {worst_racc:.3f} deg/s per s; |dstw| <= {worst_acc:.4f} m/s per s; stw {smin:.2f}..{smax:.2f} kn")
    check(worst_pos < 0.05, "track continuity")
    # truth.csv carries 4 decimals: allow that rounding
    check(worst_rate <= 1.0 + 2e-4 and worst_racc <= 0.12 and worst_acc <= 0.05 + 2e-4, "rate limits")
    if arpa:
        check(abs(smin - params["own"]["stw_kn"]) < 1e-3 and abs(smax - smin) < 1e-3, "arpa own speed constant")
    else:
        check(smin >= params["speed_min_kn"] - 2e-4 and smax <= params["speed_max_kn"] + 2e-4, "stw in range")
        for a, b in zip(params["legs"], params["legs"][1:]):
            check(abs(wrap180(b["heading_cmd_deg"] - a["heading_cmd_deg"])) <= 90 and abs(b["stw_cmd_kn"] - a["stw_cmd_kn"]) <= 3 + 1e-9 and 180 <= b["start_s"] - a["start_s"] <= 600.1, "leg limits")
    return truth


def check_turn(k, m, track, sog):
    """A --manoeuvre turn in the truth: straight before, the course turning at the stated rate during,
    the stated final course after, the speed kept."""
    check(m["end_s"] > m["start_s"] and 45 <= abs(m["turn_deg"]) <= 90 and 0.5 <= abs(m["rate_deg_s"]) <= 1.0
          and abs(m["turn_deg"] / m["rate_deg_s"] - (m["end_s"] - m["start_s"])) < 0.05, f"{k} turn parameters")
    ts = sorted(track)
    chords = []  # (mid time, azimuth) of each step between truth rows
    worst_speed = 0.0
    for a, b in zip(ts, ts[1:]):
        dist, az = inverse(*track[a], *track[b])
        worst_speed = max(worst_speed, abs(dist / (b - a) - sog))
        chords.append((0.5 * (a + b), az))
    worst_rate = 0.0  # course change between consecutive chords, per second
    for (ta, aa), (tb, ab) in zip(chords, chords[1:]):
        worst_rate = max(worst_rate, abs((ab - aa + 540) % 360 - 180) / (tb - ta))
    after = [t for t in ts if t > m["end_s"] + 5]
    if len(after) >= 2:
        az = inverse(*track[after[0]], *track[after[-1]])[1] % 360
        check(abs((az - m["cog_after_deg"] + 540) % 360 - 180) < 0.3, f"{k} course after the turn")
    check(worst_rate <= abs(m["rate_deg_s"]) * 1.05 + 0.01, f"{k} turn rate {worst_rate:.3f} deg/s")
    check(worst_speed < 0.05, f"{k} speed kept through the turn (worst {worst_speed:.3f} m/s)")


def check_arpa(d, params, truth):
    own = {round(float(r["t_s"]), 3): (float(r["lat_deg"]), float(r["lon_deg"])) for r in truth}
    tgt = defaultdict(dict)
    for r in csv.DictReader(open(f"{d}/truth_targets.csv")):
        tgt[r["target_id"]][round(float(r["t_s"]), 3)] = (float(r["lat_deg"]), float(r["lon_deg"]))
    t0 = params["t0_s"]
    xy = plane(*own[t0])  # fixed tangent plane at own ship's t0 position
    worst_cpa, worst_tcpa, worst_r = 0, 0, 0
    for p in params["targets"]:
        k = p["id"]
        def rel(t):
            (tx, ty), (ox, oy) = xy(*tgt[k][t]), xy(*own[t])
            return tx - ox, ty - oy
        h = 5.0  # relative velocity by central differences over +-5 s (truth at whole seconds, rotations at 2.5 s)
        (x, y), (x1, y1), (x0, y0) = rel(t0), rel(t0 + h), rel(t0 - h)
        vx, vy = (x1 - x0) / (2 * h), (y1 - y0) / (2 * h)
        v2 = vx * vx + vy * vy
        tcpa = -(x * vx + y * vy) / v2
        cpa = abs(x * vy - y * vx) / math.sqrt(v2)
        rng = math.hypot(x, y)
        worst_cpa = max(worst_cpa, abs(cpa - p["cpa_nm"] * 1852)); worst_tcpa = max(worst_tcpa, abs(tcpa - p["tcpa_s"]))
        worst_r = max(worst_r, abs(rng - p["range_nm"] * 1852))
        check(abs(math.sqrt(v2) / KN - p["rel_speed_kn"]) < 0.005, f"{k} relative speed")
        check(p["sog_kn"] <= 40 and 3 <= p["range_nm"] <= 11 and 8 <= p["rel_speed_kn"] <= 30 and 0 <= p["cpa_nm"] <= 2 and p["tcpa_s"] > 0, f"{k} ranges")
        # Where the CPA falls inside the run (before a --manoeuvre turn), the closest truth range
        # confirms it directly.
        m = p.get("manoeuvre")
        times = [t for t in tgt[k] if t in own and (m is None or t <= m["start_s"])]
        if m is not None:
            check_turn(k, m, tgt[k], p["sog_kn"] * KN)
        tmin = min(times, key=lambda t: math.hypot(*rel(t)))
        direct = ""
        if tmin < max(times):  # closest geodesic range in the truth
            dmin = inverse(*own[tmin], *tgt[k][tmin])[0]
            direct = f"; closest truth range {dmin/1852:.4f} NM at t={tmin:.0f} ({dmin - cpa:+.1f} m)"
            check(abs(dmin - cpa) < 60.0, f"{k} closest range vs CPA")
        print(f"  {k}: cpa {cpa/1852:.4f} NM (params {p['cpa_nm']:.4f}), tcpa {tcpa:.1f} s (params {p['tcpa_s']:.1f}){direct}")
    print(f"  worst |range - params| {worst_r:.2f} m, |cpa - params| {worst_cpa:.2f} m, |tcpa - params| {worst_tcpa:.2f} s")
    check(worst_r < 1.0 and worst_cpa < 2.0 and worst_tcpa < 0.5, "CPA/TCPA vs params")
    # Radar plots: residuals against truth interpolated at the plot time.
    per = defaultdict(list)
    rows = list(csv.DictReader(open(f"{d}/radar.csv")))
    last = ""
    for r in rows:
        check(re.fullmatch(r"2026-06-15T\d\d:\d\d:\d\d\.\d{6}Z", r["utc"]), f"radar utc {r['utc']}")
        check(r["utc"] >= last, "radar sorted"); last = r["utc"]
        check(0 <= float(r["bearing_deg"]) < 360 and float(r["range_m"]) <= 12 * 1852 + 100, "radar ranges")
        # A.823 quantisation: ranges in 0.02 NM steps, bearings in 0.2 deg steps
        for key, q in (("range_m", params["radar"]["range_quantum_m"]), ("bearing_deg", params["radar"]["bearing_quantum_deg"])):
            steps = float(r[key]) / q
            check(abs(steps - round(steps)) < 1e-3, f"radar {key} {r[key]} not a multiple of {q}")
        per[r["target_id"]].append(r)
    rb, gaps = [], []
    for k, plots in per.items():
        times = [int(p["utc"][11:13]) * 3600 + int(p["utc"][14:16]) * 60 + float(p["utc"][17:-1]) - 36000 for p in plots]
        gaps += [b - a for a, b in zip(times, times[1:])]
        for p, t in zip(plots[::10], times[::10]):
            ta = math.floor(t / 2.5) * 2.5; tb = ta + 2.5
            if tb not in tgt[k]:
                continue
            f = (t - ta) / 2.5
            lat = tgt[k][ta][0] + f * (tgt[k][tb][0] - tgt[k][ta][0]); lon = tgt[k][ta][1] + f * (tgt[k][tb][1] - tgt[k][ta][1])
            s0 = math.floor(t); g = t - s0
            o0, o1 = own[float(s0)], own.get(float(s0 + 1), own[float(s0)])
            d_, az = inverse(o0[0] + g * (o1[0] - o0[0]), o0[1] + g * (o1[1] - o0[1]), lat, lon)
            rb.append((float(p["range_m"]) - d_, wrap180(float(p["bearing_deg"]) - az)))
    mr, sr = statistics.fmean(e[0] for e in rb), statistics.pstdev(e[0] for e in rb)
    mb, sb = statistics.fmean(e[1] for e in rb), statistics.pstdev(e[1] for e in rb)
    rp = params["radar"]
    sb_model = math.sqrt(rp["gyro_scatter_sd_deg"] ** 2 + rp["bearing_random_sd_deg"] ** 2 + rp["bearing_backlash_half_width_deg"] ** 2 / 3
                         + rp["bearing_quantum_deg"] ** 2 / 12)
    print(f"  radar: {len(rows)} plots; range error mean {mr:.1f} sd {sr:.1f} m (20 m, quantisation + glint); bearing error mean {mb:.3f} "
          f"(gyro cal {rp['gyro_calibration_deg']}) sd {sb:.3f} deg ({sb_model:.3f} + glint); "
          f"plot intervals {min(gaps):.3f}..{max(gaps):.3f} s")
    check(abs(mb - params["radar"]["gyro_calibration_deg"]) < 0.1, "radar bearing bias")
    check(min(gaps) > 2.0, "plot intervals")


def main(dirs):
    for d in dirs:
        params = json.load(open(f"{d}/params.json"))
        arpa = params["generator"].endswith("arpa")
        print(f"{d}: {params['generator']} seed {params['seed']}")
        truth = check_truth(d, params, arpa)
        check_ownship_nmea(d, params, truth)
        if arpa:
            check_arpa(d, params, truth)
    for f in failures[:30]:
        print("FAIL:", f)
    print("FAILURES:", len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
