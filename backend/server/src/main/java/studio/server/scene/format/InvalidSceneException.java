package studio.server.scene.format;

import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;
import org.springframework.web.ErrorResponseException;

/**
 * A scene that cannot be rendered, with every problem found; thrown before anything is rendered.
 * Over HTTP it is a 400 "Invalid scene" problem whose {@code errors} property lists each bad field
 * by its JSON path and why (the live view sends the same problem in its messages).
 */
public final class InvalidSceneException extends ErrorResponseException {

    private final List<FieldProblem> problems;
    private final String message;

    /** @param problems at least one */
    public InvalidSceneException(List<FieldProblem> problems) {
        super(HttpStatus.BAD_REQUEST, problem(problems), null);
        this.problems = List.copyOf(problems);
        this.message = problems.stream().map(FieldProblem::toString).collect(Collectors.joining("; "));
    }

    public InvalidSceneException(String field, String message) {
        this(List.of(new FieldProblem(field, message)));
    }

    /** 400 "Invalid scene", with {@code errors}: each bad field by its JSON path and why. */
    private static ProblemDetail problem(List<FieldProblem> problems) {
        if (problems.isEmpty()) {
            throw new IllegalArgumentException("an invalid scene has at least one problem");
        }
        ProblemDetail problem = ProblemDetail.forStatus(HttpStatus.BAD_REQUEST);
        problem.setTitle("Invalid scene");
        problem.setDetail(problems.size() == 1 ? problems.get(0).toString()
                : problems.size() + " problems, the first: " + problems.get(0));
        problem.setProperty("errors", problems.stream()
                .map(p -> Map.of("field", p.field(), "message", p.message())).toList());
        return problem;
    }

    public List<FieldProblem> problems() {
        return problems;
    }

    /** Every problem, "field: why", joined by "; " (as the command line prints them). */
    @Override
    public String getMessage() {
        return message;
    }
}
