// The disk light of the soft-shadow methods (renderer/soft/DiskLight.h, thesis §5.2): centre,
// unit normal (the direction it faces) and radius.
uniform vec3 uDiskCenter;
uniform vec3 uDiskNormal;
uniform float uDiskRadius;

// |cq|^2 for the ray from receiver p through occluder o meeting the light's plane at q, or -1
// when o is not between p and the plane or q is off the disk. Operation by operation the same
// as fl::occluderHitDistance2 on the CPU (`precise`: no fused multiply-add there either), so
// CPU and GL floods choose the same occluders.
float penumbraHit(vec3 p, vec3 o) {
    precise float dx = o.x - p.x;
    precise float dy = o.y - p.y;
    precise float dz = o.z - p.z;
    precise float den = dx * uDiskNormal.x + dy * uDiskNormal.y + dz * uDiskNormal.z;
    precise float num = (uDiskCenter.x - p.x) * uDiskNormal.x +
                        (uDiskCenter.y - p.y) * uDiskNormal.y +
                        (uDiskCenter.z - p.z) * uDiskNormal.z;
    if (!(den != 0.0)) return -1.0;
    precise float s = num / den;
    if (!(s > 1.0)) return -1.0;
    precise float qx = (p.x + dx * s) - uDiskCenter.x;
    precise float qy = (p.y + dy * s) - uDiskCenter.y;
    precise float qz = (p.z + dz * s) - uDiskCenter.z;
    precise float d2 = qx * qx + qy * qy + qz * qz;
    if (!(d2 < uDiskRadius * uDiskRadius)) return -1.0;
    return d2;
}

// Area fraction of the disk beyond a chord at distance t * radius from its centre.
float segmentFraction(float t) {
    t = clamp(t, 0.0, 1.0);
    return (acos(t) - t * sqrt(1.0 - t * t)) / 3.14159265358979;
}

// Visible fraction of the light at p with occluder o, or -1 for a miss: the part holding the
// centre outside the hard shadow, the other part inside it.
float occluderIntensity(vec3 p, vec3 o, bool insideHardShadow) {
    float d2 = penumbraHit(p, o);
    if (d2 < 0.0) return -1.0;
    float seg = segmentFraction(sqrt(d2) / uDiskRadius);
    return insideHardShadow ? seg : 1.0 - seg;
}
