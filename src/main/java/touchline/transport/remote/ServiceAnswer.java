package touchline.transport.remote;

/**
 * What a robot answered to one service call, as the user sees it: the response decoded by the
 * service's response definition (CDR) or its JSON text as sent, or the server's reason the
 * call failed.
 *
 * @param service the service's name
 * @param call    the call's number (as sent in the call)
 * @param ok      true for a response, false for a failure
 * @param text    the response on one line, or why the call failed
 */
public record ServiceAnswer(String service, int call, boolean ok, String text) {

    /** One line: {@code /booster-1/check #3: success: true, message: "ok"} or {@code /b/kick #4 failed: no ball}. */
    public String describe() {
        return service + " #" + call + (ok ? ": " : " failed: ") + text;
    }
}
