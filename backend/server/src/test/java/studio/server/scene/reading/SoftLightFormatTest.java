package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;
import static studio.server.scene.reading.SceneValidationTest.assertOnlyProblem;
import static studio.server.scene.reading.SceneValidationTest.problems;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import studio.server.scene.format.FieldProblem;

/** The bad forms of a point light's radius and of an area light's fields, each named by its JSON path (issue 46). */
class SoftLightFormatTest {

    private static String light(String fields) {
        return "{'lights':[{'type':'point'},{" + fields + "}],'objects':[]}";
    }

    @Test
    void rejectsANegativeRadius() {
        assertOnlyProblem(light("'type':'point','radius':-0.5"), "lights[1].radius", "must be greater than or equal to 0");
    }

    /** Infinity also breaks the bound of 1e6: two messages, both at the field. */
    private static void assertNonFiniteAt(String scene, String field) {
        assertThat(problems(scene)).extracting("field").containsOnly(field);
        assertThat(problems(scene)).extracting("message").contains("must be a finite number");
    }

    @Test
    void rejectsANonFiniteRadius() {
        assertNonFiniteAt(light("'type':'point','radius':1e400"), "lights[1].radius");
    }

    @Test
    void rejectsARadiusThatIsNotANumber() {
        assertThat(problems(light("'type':'point','radius':'big'"))).extracting("field").containsExactly("lights[1].radius");
    }

    @Test
    void rejectsANullRadius() {
        assertOnlyProblem(light("'type':'point','radius':null"), "lights[1].radius",
                "must not be null; leave the field out for its default");
    }

    @ParameterizedTest
    @ValueSource(strings = {"[1]", "[1,2,3]", "[]"})
    void rejectsASizeThatIsNotTwoNumbers(String size) {
        assertOnlyProblem(light("'type':'area','size':" + size), "lights[1].size", "must be an array of two numbers [w, h]");
    }

    @Test
    void rejectsAZeroOrNegativeWidthOrHeight() {
        assertOnlyProblem(light("'type':'area','size':[0,1]"), "lights[1].size[0]", "must be greater than 0");
        assertOnlyProblem(light("'type':'area','size':[1,-2]"), "lights[1].size[1]", "must be greater than 0");
    }

    @Test
    void rejectsANonFiniteOrMissingSizeNumber() {
        assertNonFiniteAt(light("'type':'area','size':[1e400,1]"), "lights[1].size[0]");
        assertOnlyProblem(light("'type':'area','size':[1,null]"), "lights[1].size[1]", "must be a number");
    }

    @Test
    void rejectsALookAtThatIsNotThreeFiniteNumbers() {
        assertOnlyProblem(light("'type':'area','lookAt':[0,1]"), "lights[1].lookAt",
                "must be an array of three numbers [x, y, z]");
        // infinity is also below the coordinates' bound, and both are said
        assertThat(problems(light("'type':'area','lookAt':[0,-1e999,0]")))
                .extracting(FieldProblem::toString)
                .containsExactly("lights[1].lookAt[1]: must be a finite number",
                        "lights[1].lookAt[1]: must be greater than or equal to -1e12");
    }

    @Test
    void rejectsBadAreaLightIntensityColourAndSides() {
        assertOnlyProblem(light("'type':'area','intensity':-1"), "lights[1].intensity",
                "must be greater than or equal to 0");
        assertOnlyProblem(light("'type':'area','color':'white'"), "lights[1].color", "must be a colour of the form #rrggbb");
        assertThat(problems(light("'type':'area','twoSided':'yes'"))).extracting("field")
                .containsExactly("lights[1].twoSided");
    }

    @Test
    void rejectsAnUnknownAreaLightField() {
        assertThat(problems(light("'type':'area','radius':1"))).extracting("field").containsExactly("lights[1].radius");
    }
}
