package studio.server.preview.patch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/** RFC 6902's operations over Jackson's tree, its appendix A's examples among them, and the patches a hostile client sends. */
class JsonPatchTest {

    private static final JsonMapper JSON = JsonMapper.builder().build();

    private static JsonNode json(String text) {
        return JSON.readTree(text.replace('\'', '"'));
    }

    private static JsonNode apply(String document, String patch) {
        return JsonPatch.of(json(patch)).applyTo(json(document), 1_000_000);
    }

    private static PatchException refused(String document, String patch) {
        return assertThrows(PatchException.class, () -> apply(document, patch));
    }

    @Test
    void addsAMemberAndInsertsAnElement() {
        assertEquals(json("{'foo':'bar','baz':'qux'}"), apply("{'foo':'bar'}", "[{'op':'add','path':'/baz','value':'qux'}]"));
        assertEquals(json("{'foo':['bar','qux','baz']}"),
                apply("{'foo':['bar','baz']}", "[{'op':'add','path':'/foo/1','value':'qux'}]"));
        assertEquals(json("{'foo':['bar',['abc','def']]}"),
                apply("{'foo':['bar']}", "[{'op':'add','path':'/foo/-','value':['abc','def']}]"));
    }

    @Test
    void removesReplacesMovesAndCopies() {
        assertEquals(json("{'foo':'bar'}"), apply("{'baz':'qux','foo':'bar'}", "[{'op':'remove','path':'/baz'}]"));
        assertEquals(json("{'foo':['bar','baz']}"), apply("{'foo':['bar','qux','baz']}", "[{'op':'remove','path':'/foo/1'}]"));
        assertEquals(json("{'baz':'boo','foo':'bar'}"),
                apply("{'baz':'qux','foo':'bar'}", "[{'op':'replace','path':'/baz','value':'boo'}]"));
        assertEquals(json("{'foo':{'bar':'baz'},'qux':{'corge':'grault','thud':'fred'}}"),
                apply("{'foo':{'bar':'baz','waldo':'fred'},'qux':{'corge':'grault'}}",
                        "[{'op':'move','from':'/foo/waldo','path':'/qux/thud'}]"));
        assertEquals(json("{'foo':['all','cows','eat','grass']}"),
                apply("{'foo':['all','grass','cows','eat']}", "[{'op':'move','from':'/foo/1','path':'/foo/3'}]"));
        assertEquals(json("{'a':[1,2],'b':[1,2]}"), apply("{'a':[1,2]}", "[{'op':'copy','from':'/a','path':'/b'}]"));
        assertEquals(json("{'x':1}"), apply("{'a':2}", "[{'op':'replace','path':'','value':{'x':1}}]"));
    }

    @Test
    void unescapesTildeAndSlashInTokens() {
        assertEquals(json("{'a/b':1,'m~n':2,'':3}"),
                apply("{'a/b':0,'m~n':0}", "[{'op':'replace','path':'/a~1b','value':1},"
                        + "{'op':'replace','path':'/m~0n','value':2},{'op':'add','path':'/','value':3}]"));
        assertTrue(refused("{'a':1}", "[{'op':'remove','path':'/a~2'}]").field().equals("patch[0].path"));
        refused("{'a':1}", "[{'op':'remove','path':'/a~'}]");
        refused("{'a':1}", "[{'op':'remove','path':'a'}]");
    }

    @Test
    void testsByValueWithNumbersEqualWhateverTheirForm() {
        apply("{'a':{'x':1,'y':[true,null,'s']}}", "[{'op':'test','path':'/a','value':{'y':[true,null,'s'],'x':1.0}}]");
        PatchException failed = refused("{'a':1}", "[{'op':'test','path':'/a','value':'1'}]");
        assertEquals("patch[0].value", failed.field());
    }

    @Test
    void leavesTheDocumentAsItWasWhetherThePatchAppliesOrNot() {
        JsonNode document = json("{'objects':[{'c':[0,0,0]},{'c':[1,1,1]}],'camera':{'fov':50}}");
        JsonNode before = document.deepCopy();
        JsonNode after = JsonPatch.of(json("[{'op':'replace','path':'/objects/1/c/0','value':5},"
                + "{'op':'add','path':'/camera/up','value':[0,1,0]}]")).applyTo(document, 1000);
        assertEquals(before, document);
        assertEquals(json("{'objects':[{'c':[0,0,0]},{'c':[5,1,1]}],'camera':{'fov':50,'up':[0,1,0]}}"), after);
        assertTrue(after.get("objects").get(0) == document.get("objects").get(0), "an untouched object is linked, not copied");
        assertThrows(PatchException.class, () -> JsonPatch.of(json("[{'op':'replace','path':'/objects/0/c/0','value':9},"
                + "{'op':'remove','path':'/nothing'}]")).applyTo(document, 1000));
        assertEquals(before, document);
    }

    @Test
    void refusesPathsThatDoNotApply() {
        assertEquals("patch[0].path", refused("{'a':[1]}", "[{'op':'add','path':'/a/2','value':0}]").field());
        refused("{'a':[1]}", "[{'op':'add','path':'/a/01','value':0}]");
        refused("{'a':[1]}", "[{'op':'remove','path':'/a/-'}]");
        refused("{'a':[1]}", "[{'op':'replace','path':'/b','value':0}]");
        refused("{'a':1}", "[{'op':'add','path':'/a/b','value':0}]");
        refused("{'a':1}", "[{'op':'add','path':'/x/y','value':0}]");
        refused("{'a':1}", "[{'op':'remove','path':''}]");
        assertEquals("patch[0].from", refused("{'a':1}", "[{'op':'copy','from':'/b','path':'/c'}]").field());
    }

    @Test
    void refusesMovingAValueIntoItself() {
        assertEquals("patch[0].from", refused("{'a':{'b':{}}}", "[{'op':'move','from':'/a','path':'/a/b/c'}]").field());
        refused("{'a':{}}", "[{'op':'move','from':'','path':'/a/x'}]");
        assertEquals(json("{'a':1}"), apply("{'a':1}", "[{'op':'move','from':'/a','path':'/a'}]"));
    }

    @Test
    void refusesMalformedOperations() {
        assertEquals("patch", assertThrows(PatchException.class, () -> JsonPatch.of(json("{'op':'add'}"))).field());
        assertEquals("patch[0]", assertThrows(PatchException.class, () -> JsonPatch.of(json("[3]"))).field());
        assertEquals("patch[0].op", assertThrows(PatchException.class,
                () -> JsonPatch.of(json("[{'op':'merge','path':'/a'}]"))).field());
        assertEquals("patch[0].op", assertThrows(PatchException.class, () -> JsonPatch.of(json("[{'path':'/a'}]"))).field());
        assertEquals("patch[0].value", assertThrows(PatchException.class,
                () -> JsonPatch.of(json("[{'op':'add','path':'/a'}]"))).field());
        assertEquals("patch[0].path", assertThrows(PatchException.class,
                () -> JsonPatch.of(json("[{'op':'remove','path':5}]"))).field());
        assertEquals("patch[0].from", assertThrows(PatchException.class,
                () -> JsonPatch.of(json("[{'op':'remove','path':'/a','from':'/b'}]"))).field());
    }

    @Test
    void boundsOperationsTokensDepthAndCopies() {
        StringBuilder many = new StringBuilder("[");
        for (int i = 0; i <= JsonPatch.MAX_OPERATIONS; i++) {
            many.append(i > 0 ? "," : "").append("{'op':'test','path':'','value':{}}");
        }
        assertEquals("patch", assertThrows(PatchException.class, () -> JsonPatch.of(json(many + "]"))).field());

        String deepPath = "/a".repeat(PatchOperation.MAX_TOKENS + 1);
        assertThrows(PatchException.class, () -> JsonPatch.of(json("[{'op':'remove','path':'" + deepPath + "'}]")));

        String deepValue = "[".repeat(JsonPatch.MAX_DEPTH) + "]".repeat(JsonPatch.MAX_DEPTH);
        refused("{}", "[{'op':'add','path':'/a','value':" + deepValue + "}]");
        // a value moved ever deeper into another: each step adds levels until the bound stops it
        StringBuilder nest = new StringBuilder("[");
        for (int i = 0; i < JsonPatch.MAX_DEPTH + 5; i++) {
            nest.append(i > 0 ? "," : "").append("{'op':'add','path':'/b','value':{}},"
                    + "{'op':'move','from':'/a','path':'/b/x'},{'op':'move','from':'/b','path':'/a'}");
        }
        refused("{'a':{}}", nest + "]");

        // copies of copies would double the document at every step
        StringBuilder doubling = new StringBuilder("[");
        for (int i = 0; i < 40; i++) {
            doubling.append(i > 0 ? "," : "").append("{'op':'copy','from':'/a','path':'/a/-'}");
        }
        PatchException copies = refused("{'a':['0123456789']}", doubling + "]");
        assertTrue(copies.getMessage().contains("copies"), copies.getMessage());

        // a wide value moved deeper and back, again and again: each deeper move's look at it is counted
        StringBuilder wide = new StringBuilder("{'b':{},'a':[0");
        for (int i = 1; i < 1000; i++) {
            wide.append(',').append(i);
        }
        StringBuilder moves = new StringBuilder("[");
        for (int i = 0; i < 400; i++) {
            moves.append(i > 0 ? "," : "").append("{'op':'move','from':'/a','path':'/b/a'},{'op':'move','from':'/b/a','path':'/a'}");
        }
        JsonPatch back = JsonPatch.of(json(moves + "]"));
        JsonNode document = json(wide + "]}");
        assertEquals(document, back.applyTo(document, 1_000_000), "within the bound: moved there and back");
        assertThrows(PatchException.class, () -> back.applyTo(document, 100_000));
    }
}
