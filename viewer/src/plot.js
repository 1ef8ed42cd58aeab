// The clearance plot: distance between body and obstacles against the path parameter, with a
// cursor at the current parameter; clicking or dragging on it scrubs.

export class ClearancePlot {
  constructor(canvas, clearance, unit, onScrub) {
    this.canvas = canvas;
    this.s = clearance.s;
    this.d = clearance.distance;
    this.margin = clearance.margin ?? 0;
    this.unit = unit;
    this.cursor = 0;
    let max = 0;
    for (const v of this.d) if (Number.isFinite(v)) max = Math.max(max, v);
    this.max = max > 0 ? max * 1.08 : 1;
    let dragging = false;
    const scrub = (event) => {
      const r = canvas.getBoundingClientRect();
      const x = (event.clientX - r.left - this.left) / (r.width - this.left - this.right);
      onScrub(Math.min(1, Math.max(0, x)));
    };
    canvas.addEventListener('pointerdown', (e) => { dragging = true; canvas.setPointerCapture(e.pointerId); scrub(e); });
    canvas.addEventListener('pointermove', (e) => { if (dragging) scrub(e); });
    canvas.addEventListener('pointerup', () => { dragging = false; });
    this.left = 52;
    this.right = 10;
  }

  /** Distance at parameter s from the nearest sample (the samples are uniform in s). */
  sampleIndex(s) {
    const n = this.s.length;
    if (!n) return -1;
    let lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (this.s[mid] <= s) lo = mid; else hi = mid;
    }
    return Math.abs(this.s[hi] - s) < Math.abs(this.s[lo] - s) ? hi : lo;
  }

  draw(cursor) {
    this.cursor = cursor;
    const c = this.canvas;
    const dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth, h = c.clientHeight;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr);
      c.height = Math.round(h * dpr);
    }
    const g = c.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, w, h);
    const top = 16, bottom = 18;
    const pw = w - this.left - this.right, ph = h - top - bottom;
    const X = (s) => this.left + s * pw;
    const Y = (d) => top + ph - (Math.min(d, this.max) / this.max) * ph;
    g.font = '11px system-ui, sans-serif';
    g.fillStyle = '#ccc';
    g.fillText(`clearance (${this.unit}) along the path`, this.left, 11);
    g.strokeStyle = '#666';
    g.lineWidth = 1;
    g.beginPath();
    g.moveTo(this.left, top);
    g.lineTo(this.left, top + ph);
    g.lineTo(this.left + pw, top + ph);
    g.stroke();
    g.textAlign = 'right';
    g.fillText(this.max.toPrecision(3), this.left - 4, top + 8);
    g.fillText('0', this.left - 4, top + ph);
    g.textAlign = 'center';
    g.fillText('path parameter', this.left + pw / 2, h - 4);
    if (this.margin > 0 && this.margin < this.max) {
      g.strokeStyle = '#c55';
      g.setLineDash([4, 3]);
      g.beginPath();
      g.moveTo(X(0), Y(this.margin));
      g.lineTo(X(1), Y(this.margin));
      g.stroke();
      g.setLineDash([]);
    }
    g.strokeStyle = '#5bf';
    g.lineWidth = 1.5;
    g.beginPath();
    for (let i = 0; i < this.s.length; i++) {
      const d = Number.isFinite(this.d[i]) ? this.d[i] : this.max;
      if (i === 0) g.moveTo(X(this.s[i]), Y(d)); else g.lineTo(X(this.s[i]), Y(d));
    }
    g.stroke();
    g.strokeStyle = '#fc4';
    g.lineWidth = 1;
    g.beginPath();
    g.moveTo(X(cursor), top);
    g.lineTo(X(cursor), top + ph);
    g.stroke();
    g.textAlign = 'left';
  }
}
