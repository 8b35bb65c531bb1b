package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.lang.annotation.Annotation;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

import jakarta.validation.constraints.Email;
import jakarta.validation.constraints.Pattern;

import studio.server.scene.format.SceneDto;

/**
 * {@link SceneConstraints} is what the scene records' annotations say, so the fast path checks
 * every rule the full path's validator checks. Run with {@code -Dscene-constraints.write=true} it
 * rewrites the file instead of failing.
 */
class SceneConstraintsTest {

    private static final Path FILE = Path.of("src/main/java/studio/server/scene/reading/SceneConstraints.java");

    @Test
    void theTableIsWhatTheAnnotationsSay() throws IOException {
        SceneConstraintsSource source = SceneConstraintsSource.of(SceneDto.class);
        String expected = source.javaSource();
        if (Boolean.getBoolean("scene-constraints.write")) {
            Files.writeString(FILE, expected, StandardCharsets.UTF_8);
            return; // this run's SceneConstraints was compiled from the file before
        }
        assertThat(Files.readString(FILE, StandardCharsets.UTF_8))
                .as("SceneConstraints.java is out of date with the scene records' annotations; regenerate it "
                        + "(the command is in its class comment)")
                .isEqualTo(expected);
        assertThat(SceneConstraints.RULES).isEqualTo(source.rules());
        assertThat(SceneConstraints.SUBTYPES).isEqualTo(source.subtypes());
    }

    @Test
    void theWalkReadsTheRulesTheRecordsState() {
        SceneConstraintsSource source = SceneConstraintsSource.of(SceneDto.class);
        // a few known ones, so that an empty table cannot pass
        assertThat(source.rules()).containsEntry("ObjectDto.Sphere.radius",
                List.of(new FieldRule.Positive(), new FieldRule.Finite()));
        assertThat(source.rules()).containsEntry("ObjectDto.Sphere.center[]",
                List.of(new FieldRule.NotNull(), new FieldRule.DecimalMin("-1e12", true),
                        new FieldRule.DecimalMax("1e12", true), new FieldRule.Finite()));
        assertThat(source.subtypes()).containsKey(studio.server.scene.format.ObjectDto.class);
        assertThat(source.rules().size()).isGreaterThan(40);
    }

    record WithEmail(@Email String contact) {
    }

    record WithFlags(@Pattern(regexp = "a", flags = Pattern.Flag.CASE_INSENSITIVE) String name) {
    }

    @Test
    void aConstraintTheFastPathDoesNotCheckFailsTheBuild() {
        assertThatThrownBy(() -> SceneConstraintsSource.of(WithEmail.class))
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("Email");
        assertThatThrownBy(() -> SceneConstraintsSource.of(WithFlags.class))
                .isInstanceOf(IllegalStateException.class).hasMessageContaining("Pattern");
    }

    @Test
    void anAnnotationThatIsNoConstraintGivesNoRule() throws NoSuchFieldException {
        Annotation valid = SceneDto.class.getDeclaredField("camera").getAnnotation(jakarta.validation.Valid.class);
        assertThat(valid).isNotNull();
        assertThat(FieldRule.of(valid, "SceneDto.camera")).isNull();
    }
}
