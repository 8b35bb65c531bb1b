package studio.server.preview;

import java.util.ArrayList;
import java.util.List;

import studio.server.preview.patch.JsonPatch;
import studio.server.preview.patch.PatchOperation;

/**
 * What patches changed in a scene, told by their paths alone: for each element of the patched
 * scene's {@code objects}, the index of the element of the scene before that it is unchanged from
 * (-1 for an element added, replaced or changed inside), and whether anything outside the objects
 * changed (the camera, a light, the render settings, the name). {@code /objects/3/center} changes
 * object 3; {@code add /objects/-} adds one; {@code move} from {@code /objects/5} to
 * {@code /objects/0} moves one unchanged and shifts the others. A patch that replaces, removes or
 * moves the {@code objects} array as a whole, or the whole scene, changes every object.
 */
final class ObjectOrigins {

    private static final String OBJECTS = "objects";

    /** For each object now, where it was before, or -1; null once that cannot be followed. */
    private List<Integer> origins;
    private boolean frameChanged;

    /** No change yet to a scene of {@code count} objects. */
    ObjectOrigins(int count) {
        origins = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            origins.add(i);
        }
    }

    /** Follows a patch that applied to the scene as it is now. */
    void follow(JsonPatch patch) {
        for (PatchOperation operation : patch.operations()) {
            switch (operation.op()) {
                case ADD -> added(operation.path(), -1);
                case REMOVE -> removed(operation.path());
                case REPLACE -> {
                    removed(operation.path());
                    added(operation.path(), -1);
                }
                case MOVE -> {
                    if (!operation.from().equals(operation.path())) {
                        added(operation.path(), removed(operation.from()));
                    }
                }
                case COPY -> added(operation.path(), -1);
                case TEST -> {
                    // changes nothing
                }
            }
        }
    }

    /**
     * For each object of the patched scene, the index of the object before it is unchanged from,
     * or -1; null if every object may have changed.
     */
    int[] origins() {
        return origins == null ? null : origins.stream().mapToInt(Integer::intValue).toArray();
    }

    /** Whether anything but the objects changed. */
    boolean frameChanged() {
        return frameChanged;
    }

    /** Objects whose origin is not their own place: added, changed or moved. */
    int changed() {
        if (origins == null) {
            return Integer.MAX_VALUE;
        }
        int changed = 0;
        for (int i = 0; i < origins.size(); i++) {
            changed += origins.get(i) == i ? 0 : 1;
        }
        return changed;
    }

    /** The value at a path was removed; what was there, if it was a whole object (else -1). */
    private int removed(List<String> path) {
        int index = element(path);
        if (index >= 0 && path.size() == 2) {
            return origins.remove(index);
        }
        changedAt(path, index);
        return -1;
    }

    /** A value was placed at a path (an object whose origin is {@code origin}, if the path names an element). */
    private void added(List<String> path, int origin) {
        if (origins != null && path.size() == 2 && path.get(0).equals(OBJECTS) && path.get(1).equals("-")) {
            origins.add(origin);
            return;
        }
        int index = element(path);
        if (index >= 0 && path.size() == 2) {
            origins.add(index, origin);
            return;
        }
        changedAt(path, index);
    }

    /** A change inside an object (index >= 0), of the objects as a whole, or outside them. */
    private void changedAt(List<String> path, int index) {
        if (path.isEmpty()) {
            frameChanged = true;
            origins = null;
        } else if (!path.get(0).equals(OBJECTS)) {
            frameChanged = true;
        } else if (index >= 0 && index < origins.size()) {
            origins.set(index, -1);
        } else {
            origins = null; // the array as a whole
        }
    }

    /** The object a path lies in or names, or -1 (outside the objects, the array itself, or no longer followed). */
    private int element(List<String> path) {
        if (origins == null || path.size() < 2 || !path.get(0).equals(OBJECTS)) {
            return -1;
        }
        String token = path.get(1);
        int index = token.isEmpty() || token.length() > 9 || !token.chars().allMatch(Character::isDigit)
                ? -1 : Integer.parseInt(token);
        return index <= origins.size() ? index : -1;
    }
}
