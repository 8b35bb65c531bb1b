package studio.server.scene.format;

/** One thing wrong with a scene: the field by its JSON path (objects[2].radius) and why. */
public record FieldProblem(String field, String message) {

    @Override
    public String toString() {
        return field.isEmpty() ? message : field + ": " + message;
    }
}
