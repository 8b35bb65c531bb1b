package studio.server.scene.format;

import java.util.List;
import java.util.stream.Collectors;

/** A scene that cannot be rendered, with every problem found; thrown before anything is rendered. */
public final class InvalidSceneException extends RuntimeException {

    private final List<FieldProblem> problems;

    public InvalidSceneException(List<FieldProblem> problems) {
        super(problems.stream().map(FieldProblem::toString).collect(Collectors.joining("; ")));
        this.problems = List.copyOf(problems);
    }

    public InvalidSceneException(String field, String message) {
        this(List.of(new FieldProblem(field, message)));
    }

    public List<FieldProblem> problems() {
        return problems;
    }
}
