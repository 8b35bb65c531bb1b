package studio.bench;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * What the benchmark measured for one scene at one number of samples per pixel: every run's wall
 * time per renderer, the silhouette agreement of our mask with each peer's, and how far our
 * shaded image is from POV-Ray's.
 *
 * @param masks      our silhouette mask against each peer's
 * @param diffPovray mean absolute difference of our image and POV-Ray's, 8-bit levels (sRGB)
 */
record PeerResult(String scene, int samples, Map<Renderers.Peer, List<Long>> nanos, MaskCheck masks,
                  double diffPovray) {

    static PeerResult empty(String scene, int samples, MaskCheck masks) {
        Map<Renderers.Peer, List<Long>> nanos = new EnumMap<>(Renderers.Peer.class);
        for (Renderers.Peer peer : Renderers.Peer.values()) {
            nanos.put(peer, new ArrayList<>());
        }
        return new PeerResult(scene, samples, nanos, masks, Double.NaN);
    }

    PeerResult withDiff(double diff) {
        return new PeerResult(scene, samples, nanos, masks, diff);
    }

    /** The median wall time in milliseconds (the mean of the middle two for an even count). */
    double medianMillis(Renderers.Peer peer) {
        return median(nanos.get(peer)) / 1e6;
    }

    double ratio(Renderers.Peer peer) {
        return medianMillis(Renderers.Peer.OURS) / medianMillis(peer);
    }

    boolean masksAgree() {
        return masks.agrees();
    }

    static double median(List<Long> values) {
        if (values.isEmpty()) {
            return Double.NaN;
        }
        List<Long> sorted = values.stream().sorted().toList();
        int n = sorted.size();
        return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2.0;
    }
}
