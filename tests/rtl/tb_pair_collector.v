// Offers each vector's (hits, row, first) to the pair FIFO, holding it
// while the FIFO lacks room; drains when the vector's drain bit says so,
// then empties the FIFO. Writes every pair that leaves, "row column" in hex.
module tb_pair_collector;
    parameter M = 2;
    parameter AW = 16;
    parameter DEPTH = 16;
    parameter DISTRIBUTED = 0;
    localparam LANES = 2 * M - 1;
    reg [LANES+2*AW:0] vectors [0:65535];   // {drain, hits, row, first}
    reg clk = 0, clear = 1, ready = 0;
    reg [LANES-1:0] hits;
    reg [AW-1:0] row = 0, first = 0;
    wire room;
    wire out_valid;
    wire [2*AW-1:0] out_pair;
    integer count, v, idle, out;
    pair_collector #(.M(M), .AW(AW), .DEPTH(DEPTH), .DISTRIBUTED(DISTRIBUTED)) dut (
        .clk(clk), .clear(clear), .hits(hits), .row(row), .first(first), .drain_ready(ready),
        .room(room), .out_valid(out_valid), .out_pair(out_pair));
    task edge_and_log;
        begin
            #1 clk = 1;
            #1 clk = 0;
            if (out_valid) $fwrite(out, "%0h %0h\n", out_pair[2*AW-1 -: AW], out_pair[AW-1:0]);
        end
    endtask
    initial begin
        if (!$value$plusargs("count=%d", count)) $fatal(1, "+count=N missing");
        $readmemh("vectors.hex", vectors);
        out = $fopen("results.txt", "w");
        #1 hits = 0;  // a change, so that the FIFO's combinational logic settles
        edge_and_log;
        clear = 0;
        v = 0;
        while (v < count) begin
            {ready, hits, row, first} = vectors[v];
            #1 if (!room) ready = 1;  // (room settles first) a full FIFO must drain to move on
            if (room) v = v + 1;
            edge_and_log;
        end
        hits = 0;
        ready = 1;
        for (idle = 0; idle < 2 * DEPTH + 4; idle = idle + 1) edge_and_log;
        $fclose(out);
        $finish;
    end
endmodule
