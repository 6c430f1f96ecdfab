package touchline.bench;

/** One measured phase of the ingest benchmark: datagrams sent, decoded, and decoded per second. */
record IngestResult(long sent, long received, double perSecond) { }
