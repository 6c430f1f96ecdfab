package touchline.bench;

import picocli.CommandLine.Command;
import picocli.CommandLine.Unmatched;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code bench gc}: the GameController's send intervals on loopback against a sleep-after-send baseline. */
@Command(name = "gc", mixinStandardHelpOptions = true,
        description = "GameController send intervals vs 500 ms (options: --seconds N, --load-threads N, --warmup N, "
                + "--realtime, --hsl: the HSL schedule with its burst when play stops, --monitor-flood N: the embedded "
                + "HSL GameController with N monitor requests a second arriving).")
final class GcBenchCommand implements Callable<Integer> {

    @Unmatched
    List<String> args = new ArrayList<>();

    @Override
    public Integer call() throws Exception {
        return touchline.bench.gc.GcIntervalBenchmark.run(args.toArray(String[]::new));
    }
}
