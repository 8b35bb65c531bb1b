package studio.engine.scene;

import java.util.Arrays;

import studio.engine.accel.ShapeLeaves;
import studio.engine.geometry.Ray;

/**
 * The slots of a refitted tree whose shapes changed since its light buffers were built. A buffer
 * lists a slot in the cells its shape's box was seen in then; a shape that moved may block rays in
 * other cells. It still answers rightly for every other slot, and a hit it reports on a changed
 * slot's shape is a hit, so keeping it needs only that a shadow ray it finds nothing on tests these
 * few shapes too. Up to {@value #MAX} of them; more, and the buffers are built again: a live view's
 * drag changes the same one revision after revision, and a light buffer of 10,000 shapes takes
 * some milliseconds to build ({@code PatchRevisionBench} in the server's tests).
 */
final class StaleSlots {

    /** Most changed slots kept beside the buffers: as many as a live view's revision reads alone ({@code SceneReuse.MAX_CHANGED}). */
    static final int MAX = 8;

    private StaleSlots() {
    }

    /** The slots in either (each once, ascending), or null when they are more than {@value #MAX}. */
    static int[] union(int[] stale, int[] changed) {
        int[] all = Arrays.copyOf(stale, stale.length + changed.length);
        System.arraycopy(changed, 0, all, stale.length, changed.length);
        int[] distinct = Arrays.stream(all).sorted().distinct().toArray();
        return distinct.length <= MAX ? distinct : null;
    }

    /** Whether the shape at one of the slots lies on the ray with 0 &lt; t &lt; tMax. */
    static boolean block(int[] slots, ShapeLeaves bounded, Ray ray, double tMax) {
        for (int slot : slots) {
            if (bounded.any(slot, slot + 1, ray, tMax)) {
                return true;
            }
        }
        return false;
    }
}
