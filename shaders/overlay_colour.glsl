// Colours of the overlays (renderer/overlays/OverlayColours.h is the CPU mirror the tests compare
// the drawn pixels with; keep both operation by operation the same).

// A distinct colour per id: an integer hash (multiply-xorshift) into the range 64..191 per
// channel, so neighbouring regions differ and none is black (sites) or pure red (errors).
vec3 overlayIdColour(uint id) {
    uint h = id * 2654435761u;
    h ^= h >> 15;
    return vec3(float(64u + (h & 0x7fu)), float(64u + ((h >> 8) & 0x7fu)),
                float(64u + ((h >> 16) & 0x7fu))) / 255.0;
}

// A sequential colour map for t in [0, 1] (dark blue -> purple -> orange -> pale yellow),
// piecewise linear between five stops; values outside are clamped.
vec3 overlayRamp(float t) {
    const vec3 stops[5] = vec3[5](vec3(0.05, 0.03, 0.20), vec3(0.40, 0.10, 0.50),
                                  vec3(0.80, 0.25, 0.30), vec3(0.98, 0.60, 0.10),
                                  vec3(0.99, 0.98, 0.70));
    float s = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(s), 3);
    return mix(stops[i], stops[i + 1], s - float(i));
}
