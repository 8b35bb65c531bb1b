package studio.server.system;

import java.util.List;
import java.util.Map;

import org.springframework.http.HttpStatus;
import org.springframework.http.ProblemDetail;

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;

/** The problems (RFC 9457) that more than one API sends, built in one place. */
public final class Problems {

    private Problems() {
    }

    /** 400 "Invalid scene", with {@code errors}: each bad field by its JSON path and why. */
    public static ProblemDetail invalidScene(InvalidSceneException e) {
        List<FieldProblem> problems = e.problems();
        ProblemDetail problem = ProblemDetail.forStatus(HttpStatus.BAD_REQUEST);
        problem.setTitle("Invalid scene");
        problem.setDetail(problems.size() == 1 ? problems.get(0).toString()
                : problems.size() + " problems, the first: " + problems.get(0));
        problem.setProperty("errors", problems.stream()
                .map(p -> Map.of("field", p.field(), "message", p.message())).toList());
        return problem;
    }
}
