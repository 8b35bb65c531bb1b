package studio.server.scene.format;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.NullAndEmptySource;
import org.junit.jupiter.params.provider.ValueSource;

/** A scene's name becomes a file stem safe for a header or a file system. */
class SceneNamesTest {

    /** What every stem must look like, whatever the name. */
    private static final String SAFE = "[A-Za-z0-9_-]{1,100}";

    @Test
    void dropsPathTraversal() {
        assertThat(SceneNames.toFileStem("../../etc/passwd")).isEqualTo("etc-passwd");
    }

    @Test
    void dropsWindowsPathAndBackslashes() {
        assertThat(SceneNames.toFileStem("C:\\Users\\me\\scene")).isEqualTo("C-Users-me-scene");
    }

    @Test
    void dropsQuotes() {
        assertThat(SceneNames.toFileStem("my \"best\" 'scene'")).isEqualTo("my-best-scene");
    }

    @Test
    void dropsCarriageReturnAndLineFeed() {
        assertThat(SceneNames.toFileStem("scene\"\r\nX-Evil: 1")).isEqualTo("scene-X-Evil-1");
    }

    @Test
    void dropsOtherControlCharacters() {
        assertThat(SceneNames.toFileStem("a\u0000b\tc\u007fd")).isEqualTo("a-b-c-d");
    }

    @Test
    void stripsAccents() {
        assertThat(SceneNames.toFileStem("Café Ñandú über")).isEqualTo("Cafe-Nandu-uber");
    }

    @Test
    void keepsLettersDigitsHyphensAndUnderscores() {
        assertThat(SceneNames.toFileStem("still-life_2")).isEqualTo("still-life_2");
    }

    @Test
    void collapsesRunsOfSymbolsToOneHyphen() {
        assertThat(SceneNames.toFileStem("three   spheres!!! (v2)")).isEqualTo("three-spheres-v2");
    }

    @ParameterizedTest
    @NullAndEmptySource
    @ValueSource(strings = {"   ", "!!!", "../..", "\"\r\n", "日本語", "-_-", "..."})
    void fallsBackToRenderWhenNothingIsLeft(String name) {
        assertThat(SceneNames.toFileStem(name)).isEqualTo("render");
    }

    @Test
    void truncatesLongNamesTo100Characters() {
        assertThat(SceneNames.toFileStem("a".repeat(300))).isEqualTo("a".repeat(100));
    }

    @Test
    void truncationLeavesNoTrailingHyphen() {
        assertThat(SceneNames.toFileStem("a".repeat(99) + " " + "b".repeat(200))).isEqualTo("a".repeat(99));
    }

    @ParameterizedTest
    @ValueSource(strings = {"../../etc/passwd\"\r\nX-Evil: 1", "<script>alert(1)</script>", "a/b\\c:d*e?f|g",
            "%2e%2e%2fetc", "name;filename*=UTF-8''evil", "ﬁle ＡＢＣ"})
    void alwaysGivesSafeStem(String name) {
        assertThat(SceneNames.toFileStem(name)).matches(SAFE);
    }
}
