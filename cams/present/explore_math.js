// The explorer page's mathematics: no page, no drawing (cams explore embeds this file whole; the tests run it with
// node). camsMath(data) takes the page's data (cams/present/explore.py) and returns the functions the page calls.
//
// Roller face ("centre" mode): the cam centre O = (x, y) in the follower's fixed frame, as [cam] centre in a
// design file. The pressure angle is the kinematic inversion's (cams check's): the roller centre's velocity
// relative to the cam W = s' T - eps k x (A - O), the pitch curve's outward normal n = W turned by eps 90 deg,
// cos(gamma) = n . e with e the unit direction of the rise. The displacement s and s' = ds/dphi are interpolated
// linearly between the embedded samples; each maximum over a phase is the largest of every local maximum of the
// samples refined by golden-section search on that interpolant, and its error bound is first order in the
// interpolation's own bounds (err_s, err_ds, embedded): 2 (|d gamma/d s| err_s + |d gamma/d s'| err_ds), the
// sensitivities the largest at the maximum and a sample step either side (the interpolant's maximum and the law's
// lie within a step of each other; the factor 2 covers the second-order remainder and the sensitivities between).
function camsMath(data) {
  "use strict";
  const TOL = 1e-7; // radians: cams check's allowance over a limit
  const face = data.face;
  const phases = data.phases;
  const moving = phases.filter((p) => p.kind !== "dwell");

  function interp(ph, u) {
    if (ph.kind === "dwell") return { s: ph.level, ds: 0.0, d2s: 0.0 };
    const n = ph.n;
    const x = Math.min(Math.max(u, 0.0), 1.0) * n;
    let k = Math.floor(x);
    if (k >= n) k = n - 1;
    const t = x - k;
    return {
      s: ph.s[k] + t * (ph.s[k + 1] - ph.s[k]),
      ds: ph.ds[k] + t * (ph.ds[k + 1] - ph.ds[k]),
      d2s: ph.d2s[k] + t * (ph.d2s[k + 1] - ph.d2s[k]),
    };
  }

  // the largest of fn(s, ds) over phase ph: sampled, each local maximum refined on the interpolant
  function phaseMax(ph, fn) {
    const n = ph.n;
    const g = new Float64Array(n + 1);
    for (let k = 0; k <= n; k++) g[k] = fn(ph.s[k], ph.ds[k], ph.d2s[k]);
    const peaks = [];
    for (let k = 0; k <= n; k++) {
      const left = k > 0 ? g[k - 1] : -Infinity;
      const right = k < n ? g[k + 1] : -Infinity;
      if (g[k] >= left && g[k] >= right && g[k] > -Infinity) peaks.push(k);
    }
    peaks.sort((a, b) => g[b] - g[a]);
    let best = -Infinity;
    let bestU = 0.0;
    const f = (u) => {
      const m = interp(ph, u);
      const v = fn(m.s, m.ds, m.d2s);
      return Number.isNaN(v) ? -Infinity : v;
    };
    for (const k of peaks.slice(0, 8)) {
      if (g[k] > best) {
        best = g[k];
        bestU = k / n;
      }
      let a = Math.max(k - 1, 0) / n;
      let b = Math.min(k + 1, n) / n;
      const r = (Math.sqrt(5) - 1) / 2;
      let c = b - r * (b - a);
      let d = a + r * (b - a);
      let fc = f(c);
      let fd = f(d);
      for (let it = 0; it < 200 && b - a > 1e-15; it++) {
        if (fc >= fd) {
          b = d; d = c; fd = fc; c = b - r * (b - a); fc = f(c);
        } else {
          a = c; c = d; fc = fd; d = a + r * (b - a); fd = f(d);
        }
      }
      for (const [u, v] of [[c, fc], [d, fd], [a, f(a)], [b, f(b)]]) {
        if (v > best) {
          best = v;
          bestU = u;
        }
      }
    }
    return { value: best, u: bestU };
  }

  // one turn sampled for the profile: fn(ph, u, m, phi) at each phase's k steps (k = per in a rise or return,
  // one a degree in a dwell, at least 8), the phase's end left to the next phase; the points fn returns, in order
  function aroundProfile(per, fn) {
    const pts = [];
    for (const ph of phases) {
      const k = ph.kind === "dwell" ? Math.max(8, Math.ceil((ph.angle / (2 * Math.PI)) * 360)) : per;
      for (let j = 0; j < k; j++) {
        const u = j / k;
        pts.push(fn(ph, u, interp(ph, u), ph.start + u * ph.angle));
      }
    }
    return pts;
  }

  // one turn sampled for the chart, per phase with both ends (per steps a rise or return, 24 a dwell):
  // { index, kind, points } with the points fn(ph, u, m, phi) returns
  function perPhase(per, fn) {
    return phases.map((ph) => {
      const k = ph.kind === "dwell" ? 24 : per;
      const pts = [];
      for (let j = 0; j <= k; j++) {
        const u = j / k;
        pts.push(fn(ph, u, interp(ph, u), ph.start + u * ph.angle));
      }
      return { index: ph.index, kind: ph.kind, points: pts };
    });
  }

  // the laws at cam angle phi (rad, any turn): the interpolated s, ds, d2s of the phase holding it
  function lawsAt(phi) {
    const x = ((phi % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
    let ph = phases[phases.length - 1];
    for (const p of phases) if (x >= p.start && x < p.start + p.angle) { ph = p; break; }
    return interp(ph, (x - ph.start) / ph.angle);
  }
  const sampling = { aroundProfile, perPhase, lawsAt };

  if (face.mode === "size") return flatMath(face, phases, interp, phaseMax, sampling);

  const fol = face.follower;
  const rocker = fol.kind === "rocker";
  const eps = face.cam_sense;
  const lim = face.limits;
  const limitOf = new Map(lim.constrained.map(([i, g]) => [i, g]));
  const A0 = fol.A0;
  const pivot = fol.pivot;

  function frame(s) {
    if (rocker) {
      const th = fol.sense * s;
      const c = Math.cos(th);
      const sn = Math.sin(th);
      return { ax: fol.arm * c, ay: fol.arm * sn, tx: -fol.sense * fol.arm * sn, ty: fol.sense * fol.arm * c,
               lx: c, ly: sn };
    }
    return { ax: 0.0, ay: s, tx: 0.0, ty: 1.0, lx: 1.0, ly: 0.0 };
  }

  function normal(ox, oy, s, ds) {
    const f = frame(s);
    const rx = f.ax - ox;
    const ry = f.ay - oy;
    const wx = ds * f.tx + eps * ry;
    const wy = ds * f.ty - eps * rx;
    let nx = -eps * wy;
    let ny = eps * wx;
    const norm = Math.hypot(nx, ny);
    if (!(norm > 1e-12 * fol.scale)) return null;
    nx /= norm;
    ny /= norm;
    const t = Math.hypot(f.tx, f.ty);
    return { nx, ny, ex: f.tx / t, ey: f.ty / t, rx, ry, wx, wy, f };
  }

  function gamma(ox, oy, s, ds) {
    const n = normal(ox, oy, s, ds);
    if (n === null) return -Infinity;
    return Math.acos(Math.min(1.0, Math.max(-1.0, n.nx * n.ex + n.ny * n.ey)));
  }

  function crossing(px, py, dx, dy, lx, ly) {
    const den = lx * dy - ly * dx;
    return den !== 0.0 ? (px * dy - py * dx) / den : NaN;
  }

  // seed 3.26: the two lines of a position moved by K_C; the larger sine of the excess (> 0 outside)
  function kcExcess(ox, oy, s, ds, limit) {
    const n = normal(ox, oy, s, ds);
    if (n === null) return -Infinity;
    const px = ox - pivot[0];
    const py = oy - pivot[1];
    const c = Math.cos(limit);
    const sn = Math.sin(limit);
    const lx = n.f.lx;
    const ly = n.f.ly;
    const rhoD = crossing(px, py, n.nx, n.ny, lx, ly);
    const rhoOut = crossing(px, py, c * n.ex + sn * lx, c * n.ey + sn * ly, lx, ly);
    const rhoIn = crossing(px, py, c * n.ex - sn * lx, c * n.ey - sn * ly, lx, ly);
    const K = lim.safety_factor;
    const poleOut = rhoD + (K - 1.0) * fol.arm;
    const poleIn = rhoD - (1.0 - 1.0 / K) * fol.arm;
    const out0 = c * (poleOut - rhoOut);
    const out1 = c * (rhoIn - poleIn);
    const r0 = Math.hypot(px - poleOut * lx, py - poleOut * ly);
    const r1 = Math.hypot(px - poleIn * lx, py - poleIn * ly);
    const v0 = r0 > 0 ? out0 / r0 : out0;
    const v1 = r1 > 0 ? out1 / r1 : out1;
    if (Number.isNaN(v0) || Number.isNaN(v1)) return -Infinity;
    return Math.max(v0, v1);
  }

  // first-order bound of a maximum's error from the interpolation's bounds (radians)
  // (the sensitivities taken as their largest at the maximum and a step either side of it)
  function bound(ph, ox, oy, u) {
    const h = 1e-6 * (rocker ? 1.0 : fol.scale);
    let gs = 0.0;
    let gd = 0.0;
    for (const v of [u - 1 / ph.n, u, u + 1 / ph.n]) {
      const m = interp(ph, Math.min(1, Math.max(0, v)));
      gs = Math.max(gs, Math.abs(gamma(ox, oy, m.s + h, m.ds) - gamma(ox, oy, m.s - h, m.ds)) / (2 * h));
      gd = Math.max(gd, Math.abs(gamma(ox, oy, m.s, m.ds + h) - gamma(ox, oy, m.s, m.ds - h)) / (2 * h));
    }
    return 2.0 * (gs * ph.err_s + gd * ph.err_ds) + 1e-12;
  }

  const deg = (x) => (x * 180.0) / Math.PI;

  // everything the page shows of the cam centred at (ox, oy) but the curves
  function evaluate(ox, oy) {
    const res = { rise: null, ret: null, riseAt: null, retAt: null, risePhases: [], returnPhases: [],
                  perPhase: [], bound: 0.0, kc: null };
    for (const ph of moving) {
      const r = phaseMax(ph, (s, ds) => gamma(ox, oy, s, ds));
      if (!(r.value > -Infinity)) continue;
      const b = bound(ph, ox, oy, r.u);
      const at = ph.start + r.u * ph.angle;
      res.perPhase.push({ index: ph.index, kind: ph.kind, value: r.value, at, bound: b,
                          limit: limitOf.has(ph.index) ? limitOf.get(ph.index) : null });
      res.bound = Math.max(res.bound, b);
      if (ph.kind === "rise") {
        res.risePhases.push(ph.index);
        if (res.rise === null || r.value > res.rise) { res.rise = r.value; res.riseAt = at; }
      } else {
        res.returnPhases.push(ph.index);
        if (res.ret === null || r.value > res.ret) { res.ret = r.value; res.retAt = at; }
      }
    }
    let ok = res.rise === null || res.rise <= lim.pressure_angle + TOL;
    if (lim.closure === "form" && res.ret !== null) ok = ok && res.ret <= lim.return_limit + TOL;
    res.pressureOk = ok;
    if (rocker && lim.safety_factor > 1.0 && lim.constrained.length) {
      let ex = -Infinity;
      let where = null;
      for (const ph of moving) {
        if (!limitOf.has(ph.index)) continue;
        const g = limitOf.get(ph.index);
        const r = phaseMax(ph, (s, ds) => kcExcess(ox, oy, s, ds, g));
        if (r.value > ex) { ex = r.value; where = { index: ph.index, at: ph.start + r.u * ph.angle }; }
      }
      res.kc = { excess: ex, ok: ex <= TOL, where };
    }
    res.inside = ok && (res.kc === null || res.kc.ok);
    const R0 = Math.hypot(ox - A0[0], oy - A0[1]);
    res.R0 = R0;
    res.L = rocker ? Math.hypot(ox - pivot[0], oy - pivot[1]) : null;
    res.offset = rocker ? null : -ox + 0.0;
    return res;
  }

  // window.cams.state()'s object for the centre (ox, oy): lengths in the file's unit, angles in degrees
  function state(ox, oy) {
    const r = evaluate(ox, oy);
    return {
      centre: [ox, oy], R0: r.R0, L: r.L, offset: r.offset,
      max_pressure_angle: { rise: r.rise === null ? null : deg(r.rise), return: r.ret === null ? null : deg(r.ret) },
      inside: r.inside, error_bound: deg(r.bound),
    };
  }

  // the pressure angle over the cycle (degrees against cam angle in degrees), per phase
  function cycle(ox, oy, per = 240) {
    return perPhase(per, (ph, u, m, phi) => {
      const g = gamma(ox, oy, m.s, m.ds);
      return [deg(phi), g > -Infinity ? deg(g) : null];
    });
  }

  // the pitch curve and working profile in the cam frame (cam angle 0 in the fixed frame), the radius of
  // curvature of the pitch curve (> 0 convex) and where the roller undercuts it (convex, radius below the roller's)
  function profile(ox, oy, per = 360) {
    const rr = fol.roller_radius;
    return aroundProfile(per, (ph, u, m, phi) => {
      const f = frame(m.s);
      const rx = f.ax - ox;
      const ry = f.ay - oy;
      // w = r' - eps J r, r' = T s'; w2 = w' - eps J w, w' = r'' - eps J r', r'' = T' s'^2 + T s''
      const r1x = f.tx * m.ds;
      const r1y = f.ty * m.ds;
      const wx = r1x + eps * ry;
      const wy = r1y - eps * rx;
      const dTx = rocker ? -f.ax : 0.0;
      const dTy = rocker ? -f.ay : 0.0;
      const r2x = dTx * m.ds * m.ds + f.tx * m.d2s;
      const r2y = dTy * m.ds * m.ds + f.ty * m.d2s;
      const w1x = r2x + eps * r1y;
      const w1y = r2y - eps * r1x;
      const w2x = w1x + eps * wy;
      const w2y = w1y - eps * wx;
      const wn = Math.hypot(wx, wy);
      const kappa = (wx * w2y - wy * w2x) / (wn * wn * wn);
      const rho = 1.0 / (-eps * kappa);
      // into the cam frame: rotate by -eps phi
      const c = Math.cos(-eps * phi);
      const s = Math.sin(-eps * phi);
      const px = c * rx - s * ry;
      const py = s * rx + c * ry;
      const nfx = (-eps * wy) / wn;
      const nfy = (eps * wx) / wn;
      const nx = c * nfx - s * nfy;
      const ny = s * nfx + c * nfy;
      return { phi, pitch: [px, py], work: [px - rr * nx, py - rr * ny], outer: [px + rr * nx, py + rr * ny],
               rho, undercut: rr > 0 && rho > 0 && rho < rr, s: m.s };
    });
  }

  // the follower at cam angle phi: its displacement and the roller centre (fixed frame)
  function follower(phi) {
    const m = lawsAt(phi);
    const f = frame(m.s);
    return { s: m.s, A: [f.ax, f.ay] };
  }

  return { face, phases, interp, phaseMax, gamma, kcExcess, evaluate, state, cycle, profile, follower, frame,
           deg, TOL };
}

// A flat face ("size" mode): R0 and, for a rocker, L are moved (the face offset f or the axis offset e stay the
// file's). The face is a line with unit normal m at angle a from the cam centre's frame (fixed), at distance p from
// the cam centre (the support function); in the cam frame its normal turns to theta = a - eps phi. Translating:
// a = 90 deg, p = R0 + s. Rocker (the line-of-centres frame, pivot at (-L, 0) from the cam centre): a = a0 + sigma s,
// cos a0 = (f - R0) / L, p = f - L cos a. The profile is the envelope X = p m + (p' / theta') t, its radius of
// curvature rho = p + (p'' theta' - p' theta'') / theta'^3, the contact on a rocker's face c = -sigma (-L sin a +
// p' / theta') from the pivot's foot and its pressure angle atan(|f| / |c|) (0 for a translating face).
function flatMath(face, phases, interp, phaseMax, sampling) {
  "use strict";
  const fol = face.follower;
  const rocker = fol.kind === "rocker";
  const eps = face.cam_sense;
  const moving = phases.filter((p) => p.kind !== "dwell");
  const lift = Math.max(...phases.map((p) => p.level), ...moving.map((p) => Math.max(...p.s)));
  const deg = (x) => (x * 180.0) / Math.PI;

  // why no cam of this size can be drawn (a rocker's face that cannot touch the base circle), or null
  function invalid(R0, L) {
    if (!(R0 > 0)) return "R0 must be > 0";
    if (!rocker) return null;
    if (!(L > 0)) return "L must be > 0";
    const c = (fol.face_offset - R0) / L;
    if (!(c > -1 && c < 1)) return "the face cannot touch a base circle of R0 = " + R0 + " (|f - R0| >= L = " + L + ")";
    if (Math.acos(c) + lift >= Math.PI) return "the face would turn past the line of centres during the rise";
    return null;
  }

  function terms(R0, L, s, ds, d2s) {
    if (!rocker) return { a: Math.PI / 2, t1: -eps, t2: 0.0, p: R0 + s, p1: ds, p2: d2s };
    const sg = fol.sense;
    const a0 = sg * Math.acos(Math.min(1, Math.max(-1, (fol.face_offset - R0) / L)));
    const a = a0 + sg * s;
    const sa = Math.sin(a), ca = Math.cos(a);
    return { a, t1: sg * ds - eps, t2: sg * d2s, p: fol.face_offset - L * ca, p1: L * sa * sg * ds,
             p2: L * ca * ds * ds + L * sa * sg * d2s };
  }
  const rhoOf = (t) => t.p + (t.p2 * t.t1 - t.p1 * t.t2) / (t.t1 * t.t1 * t.t1);
  function gammaOf(L, t) {
    if (!rocker) return 0.0;
    const c = -fol.sense * (-L * Math.sin(t.a) + t.p1 / t.t1);
    return Math.atan2(Math.abs(fol.face_offset), Math.abs(c));
  }

  // first-order bound of an extremum's error from the interpolation's bounds
  function bound(ph, u, value) {
    const h = 1e-6 * (rocker ? 1.0 : fol.scale);
    let out = 0.0;
    for (const v of [u - 1 / ph.n, u, u + 1 / ph.n]) {
      const m = interp(ph, Math.min(1, Math.max(0, v)));
      const d = (ds0, dd0, d20) => Math.abs(value(m.s + ds0, m.ds + dd0, m.d2s + d20) -
                                            value(m.s - ds0, m.ds - dd0, m.d2s - d20)) / (2 * h);
      out = Math.max(out, d(h, 0, 0) * ph.err_s + d(0, h, 0) * ph.err_ds + d(0, 0, h) * ph.err_d2s);
    }
    return 2.0 * out + 1e-12;
  }

  function evaluate(R0, L) {
    const res = { R0, L: rocker ? L : null, offset: rocker ? null : fol.offset, rise: null, ret: null,
                  risePhases: [], returnPhases: [], bound: 0.0, minRho: Infinity, minRhoAt: null, rhoBound: 0.0,
                  invalid: invalid(R0, L) };
    if (res.invalid !== null) { res.inside = false; return res; }
    for (const ph of phases) {
      if (ph.kind === "dwell") {
        const r = rhoOf(terms(R0, L, ph.level, 0, 0));
        if (r < res.minRho) { res.minRho = r; res.minRhoAt = ph.start; }
        continue;
      }
      const rho = (s, ds, d2s) => rhoOf(terms(R0, L, s, ds, d2s));
      const lo = phaseMax(ph, (s, ds, d2s) => -rho(s, ds, d2s));
      if (-lo.value < res.minRho) { res.minRho = -lo.value; res.minRhoAt = ph.start + lo.u * ph.angle; }
      res.rhoBound = Math.max(res.rhoBound, bound(ph, lo.u, rho));
      const gam = (s, ds, d2s) => gammaOf(L, terms(R0, L, s, ds, d2s));
      const hi = phaseMax(ph, gam);
      res.bound = Math.max(res.bound, rocker ? bound(ph, hi.u, gam) : 0.0);
      if (ph.kind === "rise") {
        res.risePhases.push(ph.index);
        res.rise = res.rise === null ? hi.value : Math.max(res.rise, hi.value);
      } else {
        res.returnPhases.push(ph.index);
        res.ret = res.ret === null ? hi.value : Math.max(res.ret, hi.value);
      }
    }
    res.inside = res.minRho >= face.limits.min_radius - 1e-9 * fol.scale;
    return res;
  }

  function state(R0, L) {
    const r = evaluate(R0, L);
    return { centre: null, R0, L: r.L, offset: r.offset,
             max_pressure_angle: { rise: r.rise === null ? null : deg(r.rise), return: r.ret === null ? null : deg(r.ret) },
             inside: r.inside, error_bound: deg(r.bound) };
  }

  // the profile in the cam frame: the envelope's points, their radius of curvature, the face's normal angle
  function profile(R0, L, per = 360) {
    return sampling.aroundProfile(per, (ph, u, m, phi) => {
      const t = terms(R0, L, m.s, m.ds, m.d2s);
      const th = t.a - eps * phi;
      const pt = t.p1 / t.t1;
      const X = [t.p * Math.cos(th) - pt * Math.sin(th), t.p * Math.sin(th) + pt * Math.cos(th)];
      return { phi, work: X, rho: rhoOf(t), a: t.a, p: t.p, s: m.s };
    });
  }

  function cycle(R0, L, per = 240) {
    return sampling.perPhase(per, (ph, u, m, phi) => {
      const t = terms(R0, L, m.s, m.ds, m.d2s);
      return [deg(phi), rhoOf(t), deg(gammaOf(L, t))];
    });
  }

  function follower(R0, L, phi) {
    const m = sampling.lawsAt(phi);
    const t = terms(R0, L, m.s, m.ds, m.d2s);
    return { s: m.s, a: t.a, p: t.p, contact: t.p1 / t.t1 };
  }

  return { face, phases, interp, phaseMax, invalid, terms, evaluate, state, profile, cycle, follower, deg };
}

if (typeof module !== "undefined") module.exports = { camsMath };
