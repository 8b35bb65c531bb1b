package studio.server.scene.compiling;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;

/**
 * The problems found while a scene is mapped, in the order found, so that one response lists them
 * all; {@link #throwIfAny} ends the mapping before anything is built from a scene that has one.
 */
final class MappingProblems {

    private final List<FieldProblem> list = new ArrayList<>();

    void add(String field, String message) {
        list.add(new FieldProblem(field, message));
    }

    void atMost(String field, int value, int max) {
        if (value > max) {
            list.add(new FieldProblem(field, "must be at most " + max + " (this server's limit), not " + value));
        }
    }

    void atMost(String field, int count, int max, String what) {
        if (count > max) {
            list.add(new FieldProblem(field, "has " + count + " " + what + "; this server's limit is " + max));
        }
    }

    /**
     * Runs an engine constructor; its IllegalArgumentException becomes a problem at {@code field}
     * (a {@link FieldException} at the field it names). Null if it failed.
     */
    <T> T attempt(String field, Supplier<T> build) {
        try {
            return build.get();
        } catch (FieldException e) {
            list.add(new FieldProblem(e.field, e.getMessage()));
        } catch (IllegalArgumentException e) {
            list.add(new FieldProblem(field, e.getMessage()));
        }
        return null;
    }

    /** Whether a problem names {@code field}. */
    boolean has(String field) {
        return list.stream().anyMatch(p -> p.field().equals(field));
    }

    /** @throws InvalidSceneException listing every problem, if there is one */
    void throwIfAny() {
        if (!list.isEmpty()) {
            throw new InvalidSceneException(list);
        }
    }

    /** A problem found while mapping, already naming its field. */
    static final class FieldException extends RuntimeException {
        final String field;

        FieldException(String field, String message) {
            super(message);
            this.field = field;
        }
    }
}
