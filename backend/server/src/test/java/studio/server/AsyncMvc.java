package studio.server;

import static org.springframework.test.web.servlet.request.MockMvcRequestBuilders.asyncDispatch;

import org.springframework.test.web.servlet.MockMvc;
import org.springframework.test.web.servlet.MvcResult;
import org.springframework.test.web.servlet.RequestBuilder;
import org.springframework.test.web.servlet.ResultActions;

/**
 * MockMvc for endpoints that answer asynchronously (POST /api/render waits for its render without
 * holding the request thread): performs the request and, if it went asynchronous, waits for the
 * result and dispatches it, so the expectations see the final response.
 */
public final class AsyncMvc {

    private AsyncMvc() {
    }

    public static ResultActions perform(MockMvc mvc, RequestBuilder request) throws Exception {
        ResultActions first = mvc.perform(request);
        MvcResult result = first.andReturn();
        if (!result.getRequest().isAsyncStarted()) {
            return first;
        }
        result.getAsyncResult(120_000);
        return mvc.perform(asyncDispatch(result));
    }
}
