package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;

/** The placement's loops over triangles, which run {@link Runs#LENGTH} triangles a call. */
class MeshPlacementTest {

    /** Triangle t: (t, t, 0), (t + 1, t, 0), (t, t + 1, 0); every seventh made flat (its third corner on the first). */
    private static final int TRIANGLES = 5 * Runs.LENGTH + 3;

    private static double[] positions() {
        double[] p = new double[9 * TRIANGLES];
        for (int t = 0; t < TRIANGLES; t++) {
            double[] corners = {t, t, 0, t + 1, t, 0, t, t + 1, 0};
            if (t % 7 == 3) {
                corners[6] = t;
                corners[7] = t;
            }
            System.arraycopy(corners, 0, p, 9 * t, 9);
        }
        return p;
    }

    private static int[] indices() {
        int[] indices = new int[3 * TRIANGLES];
        Arrays.setAll(indices, i -> i);
        return indices;
    }

    @Test
    void nonDegenerateKeepsEveryTriangleWithAreaInOrderAcrossRuns() {
        int[] kept = MeshPlacement.nonDegenerate(indices(), positions());

        int[] expected = IntStream.range(0, TRIANGLES).filter(t -> t % 7 != 3)
                .flatMap(t -> IntStream.of(3 * t, 3 * t + 1, 3 * t + 2)).toArray();
        assertArrayEquals(expected, kept);
    }

    @Test
    void haveAreaIsFalseWhenAnyTriangleIsFlatEvenInTheLastRun() {
        double[] p = positions();
        int[] all = indices();
        int[] withArea = MeshPlacement.nonDegenerate(all, p);
        assertTrue(MeshPlacement.haveArea(withArea, p));
        assertFalse(MeshPlacement.haveArea(all, p));
        int last = TRIANGLES - 1; // made flat alone, in the last run
        p[9 * last + 6] = last;
        p[9 * last + 7] = last;
        int[] lastFlat = Arrays.copyOf(withArea, withArea.length);
        System.arraycopy(all, 3 * last, lastFlat, lastFlat.length - 3, 3);
        assertFalse(MeshPlacement.haveArea(lastFlat, p));
    }
}
