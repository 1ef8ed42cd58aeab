// The body's motion along the path: the same interpolation as swept::interpolate (the body-frame
// reference point moves on a straight line, the rotation is the shortest-arc slerp about it).
import { Quaternion, Vector3 } from 'three';

export class PathMotion {
  /**
   * @param waypoints [{s, translation: [x,y,z], quaternion: [x,y,z,w]}], s increasing in [0, 1]
   * @param reference body-frame point [x,y,z]
   */
  constructor(waypoints, reference) {
    if (!waypoints.length) throw new Error('the path has no poses');
    this.s = waypoints.map((w) => w.s);
    this.q = waypoints.map((w) => new Quaternion(...w.quaternion).normalize());
    this.t = waypoints.map((w) => new Vector3(...w.translation));
    this.reference = new Vector3(...reference);
    // World position of the reference point at each waypoint.
    this.c = this.q.map((q, i) => this.reference.clone().applyQuaternion(q).add(this.t[i]));
  }

  /** Pose at path parameter s ∈ [0, 1]: writes the body frame's quaternion and translation. */
  poseAt(s, quaternion, translation) {
    const n = this.s.length;
    s = Math.min(1, Math.max(0, s));
    let i = 0;
    while (i + 2 < n && this.s[i + 1] <= s) i++;
    if (n === 1) {
      quaternion.copy(this.q[0]);
      translation.copy(this.t[0]);
      return;
    }
    const span = this.s[i + 1] - this.s[i];
    const u = span > 0 ? Math.min(1, Math.max(0, (s - this.s[i]) / span)) : 1;
    quaternion.slerpQuaternions(this.q[i], this.q[i + 1], u);
    const c = this.c[i].clone().lerp(this.c[i + 1], u);
    translation.copy(c.sub(this.reference.clone().applyQuaternion(quaternion)));
  }
}
